#include "core/base/atomic_file.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kerf {

namespace {

Diagnostic ioError(const std::filesystem::path& path, const char* what) {
    return Diagnostic::make(Severity::Error, "io", path.string(), 0, 0,
                            KERF_TR_NOOP("cannot {1}: {2}"), what, std::strerror(errno));
}

bool writeAll(int fd, std::string_view content) {
    const char* data = content.data();
    size_t left = content.size();
    while (left > 0) {
        ssize_t written = ::write(fd, data, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data += written;
        left -= static_cast<size_t>(written);
    }
    return true;
}

}  // namespace

MaybeError writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
    std::filesystem::path folder = path.parent_path();
    if (folder.empty()) folder = ".";
    std::string tempName = (folder / ("." + path.filename().string() + ".XXXXXX")).string();
    int fd = ::mkstemp(tempName.data());
    if (fd < 0) return ioError(path, "create a temporary file");
    bool ok = writeAll(fd, content) && ::fsync(fd) == 0;
    ok = (::close(fd) == 0) && ok;
    if (ok) {
        // Keep the permissions of the file we replace, or use the usual 0644.
        struct stat info {};
        mode_t mode = ::stat(path.c_str(), &info) == 0 ? (info.st_mode & 07777) : 0644;
        ::chmod(tempName.c_str(), mode);
    }
    if (!ok || ::rename(tempName.c_str(), path.c_str()) != 0) {
        Diagnostic error = ioError(path, "write the file");
        ::unlink(tempName.c_str());
        return error;
    }
    int dirFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
    if (dirFd >= 0) {
        ::fsync(dirFd);
        ::close(dirFd);
    }
    return std::nullopt;
}

Expected<std::string> readWholeFile(const std::filesystem::path& path) {
    // POSIX calls rather than streams: no exceptions, and a directory is an error, not a throw.
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return ioError(path, "open the file");
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        if (errno == 0 || S_ISDIR(info.st_mode)) errno = EISDIR;
        Diagnostic error = ioError(path, "read the file");
        ::close(fd);
        return error;
    }
    std::string content;
    content.resize(static_cast<size_t>(info.st_size));
    size_t done = 0;
    while (done < content.size()) {
        ssize_t n = ::read(fd, content.data() + done, content.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<size_t>(n);
    }
    ::close(fd);
    content.resize(done);
    return content;
}

}  // namespace kerf
