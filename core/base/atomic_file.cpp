#include "core/base/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

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
    std::ifstream in(path, std::ios::binary);
    if (!in) return ioError(path, "open the file");
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return ioError(path, "read the file");
    return content;
}

}  // namespace kerf
