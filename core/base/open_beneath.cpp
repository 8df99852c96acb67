#include "core/base/open_beneath.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <linux/openat2.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace kerf {

FileDescriptor& FileDescriptor::operator=(FileDescriptor&& other) noexcept {
    if (this != &other) {
        if (m_fd >= 0) ::close(m_fd);
        m_fd = other.release();
    }
    return *this;
}

FileDescriptor::~FileDescriptor() {
    if (m_fd >= 0) ::close(m_fd);
}

int FileDescriptor::release() {
    int fd = m_fd;
    m_fd = -1;
    return fd;
}

namespace {

int openat2Beneath(int rootFd, const char* relative, int flags) {
    open_how how{};
    how.flags = static_cast<unsigned long long>(flags | O_CLOEXEC);
    how.mode = 0;
    how.resolve = RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS | RESOLVE_NO_MAGICLINKS;
    for (;;) {
        long fd = ::syscall(SYS_openat2, rootFd, relative, &how, sizeof how);
        // EAGAIN: a rename elsewhere raced the lookup; the kernel asks to try again.
        if (fd < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        return static_cast<int>(fd);
    }
}

}  // namespace

Expected<FileDescriptor> openBeneath(const std::filesystem::path& root,
                                     const std::filesystem::path& relative, int flags) {
    const std::filesystem::path name = root / relative;
    auto cannotOpen = [&] {
        return Diagnostic::make(Severity::Error, "io", name.string(), 0, 0,
                                KERF_TR_NOOP("cannot {1}: {2}"), "open the file",
                                std::strerror(errno));
    };
    FileDescriptor rootFd(::open(root.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC));
    if (rootFd.get() < 0) return cannotOpen();
    const char* below = relative.empty() ? "." : relative.c_str();
    int fd = openat2Beneath(rootFd.get(), below, flags);
    if (fd < 0 && (errno == ENOSYS || errno == EPERM)) {
        // No openat2 (old kernel, or a sandbox that filters it).
        fd = ::openat(rootFd.get(), below, flags | O_CLOEXEC | O_NOFOLLOW);
    }
    if (fd >= 0) return FileDescriptor(fd);
    if (errno == ELOOP || errno == EXDEV) {
        return Diagnostic::make(Severity::Error, "path", name.string(), 0, 0,
                                KERF_TR_NOOP("'{1}' changed while it was opened: a link appeared"),
                                name.string());
    }
    return cannotOpen();
}

}  // namespace kerf
