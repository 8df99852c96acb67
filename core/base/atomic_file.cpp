#include "core/base/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/base/open_beneath.h"

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

// A new, empty file ".name.XXXXXX" in the folder (mkstemp has no form that takes a folder).
int createTemporary(int folderFd, const std::string& fileName, std::string& tempName) {
    static constexpr char kLetters[] =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    std::random_device seed;
    std::mt19937 random(seed());
    std::uniform_int_distribution<size_t> pick(0, sizeof kLetters - 2);
    for (int attempt = 0; attempt < 100; ++attempt) {
        tempName = "." + fileName + ".";
        for (int i = 0; i < 6; ++i)
            tempName += kLetters[pick(random)];
        int fd = ::openat(folderFd, tempName.c_str(),
                          O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    return -1;
}

}  // namespace

Diagnostic notRegular(const std::filesystem::path& path) {
    return Diagnostic::make(Severity::Error, "io", path.string(), 0, 0,
                            KERF_TR_NOOP("'{1}' is not a regular file"), path.string());
}

MaybeError writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
    std::filesystem::path folder = path.parent_path();
    if (folder.empty()) folder = ".";
    FileDescriptor folderFd(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (folderFd.get() < 0) return ioError(path, "open the folder");
    return writeFileAtomicallyAt(folderFd.get(), path.filename().string(), path, content);
}

MaybeError writeFileAtomicallyAt(int folderFd, const std::string& fileName,
                                 const std::filesystem::path& path, std::string_view content) {
    // stat follows a link here on purpose: a link to a FIFO or a device is refused as well.
    struct stat existing {};
    const bool exists = ::fstatat(folderFd, fileName.c_str(), &existing, 0) == 0;
    if (exists && !S_ISREG(existing.st_mode)) return notRegular(path);
    std::string tempName;
    int fd = createTemporary(folderFd, fileName, tempName);
    if (fd < 0) return ioError(path, "create a temporary file");
    // Keep the permissions of the file we replace, or use the usual 0644.
    bool ok = ::fchmod(fd, exists ? (existing.st_mode & 07777) : 0644) == 0;
    ok = ok && writeAll(fd, content) && ::fsync(fd) == 0;
    ok = (::close(fd) == 0) && ok;
    // renameat replaces the name itself: a link there is replaced, never written through.
    if (!ok || ::renameat(folderFd, tempName.c_str(), folderFd, fileName.c_str()) != 0) {
        Diagnostic error = ioError(path, "write the file");
        ::unlinkat(folderFd, tempName.c_str(), 0);
        return error;
    }
    ::fsync(folderFd);
    return std::nullopt;
}

Expected<std::string> readWholeFile(const std::filesystem::path& path) {
    // POSIX calls rather than streams: no exceptions, and a directory is an error, not a throw.
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below like a device.
    FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY));
    if (fd.get() < 0) return ioError(path, "open the file");
    return readOpenFile(fd.get(), path);
}

Expected<std::string> readOpenFile(int fd, const std::filesystem::path& path) {
    struct stat info {};
    if (::fstat(fd, &info) != 0) return ioError(path, "read the file");
    if (!S_ISREG(info.st_mode)) return notRegular(path);
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
        if (n < 0) return ioError(path, "read the file");
        if (n == 0) break;
        if (!inPlace) content.append(more, static_cast<size_t>(n));
        done += static_cast<size_t>(n);
    }
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
