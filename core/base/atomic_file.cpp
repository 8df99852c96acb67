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

Diagnostic notRegular(const std::filesystem::path& path) {
    return Diagnostic::make(Severity::Error, "io", path.string(), 0, 0,
                            KERF_TR_NOOP("'{1}' is not a regular file"), path.string());
}

MaybeError writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode)) return notRegular(path);
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
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below like a device.
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return ioError(path, "open the file");
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        Diagnostic error = ioError(path, "read the file");
        ::close(fd);
        return error;
    }
    if (!S_ISREG(info.st_mode)) {
        ::close(fd);
        return notRegular(path);
    }
    std::string content;
    content.resize(static_cast<size_t>(info.st_size));
    size_t done = 0;
    char more[4096];
    for (;;) {
        // After the size fstat gave, keep reading into a small buffer: a file that grew in the
        // meantime is still read whole, without reallocating a large one.
        const bool inPlace = done < content.size();
        char* into = inPlace ? content.data() + done : more;
        const size_t room = inPlace ? content.size() - done : sizeof more;
        ssize_t n = ::read(fd, into, room);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            Diagnostic error = ioError(path, "read the file");
            ::close(fd);
            return error;
        }
        if (n == 0) break;
        if (!inPlace) content.append(more, static_cast<size_t>(n));
        done += static_cast<size_t>(n);
    }
    ::close(fd);
    content.resize(done);
    return content;
}

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
    struct stat first {};
    struct stat second {};
    if (::stat(a.c_str(), &first) != 0 || ::stat(b.c_str(), &second) != 0) return false;
    return first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

}  // namespace kerf
