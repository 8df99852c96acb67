#pragma once

#include <filesystem>

#include "core/base/expected.h"

namespace kerf {

// An open file descriptor that is closed with its owner.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : m_fd(fd) {}
    FileDescriptor(FileDescriptor&& other) noexcept : m_fd(other.release()) {}
    FileDescriptor& operator=(FileDescriptor&& other) noexcept;
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor();

    int get() const { return m_fd; }
    int release();

private:
    int m_fd = -1;
};

// Opens `relative` (a path without links, as NcRoot::contains resolved it) below the folder
// `root` with the open(2) `flags`, in one step that follows no link and cannot leave `root`
// (openat2 with RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS). So a link swapped into the path after the
// name was checked is refused instead of followed. Where the kernel has no openat2 (before
// Linux 5.6) only the last name is protected (O_NOFOLLOW).
Expected<FileDescriptor> openBeneath(const std::filesystem::path& root,
                                     const std::filesystem::path& relative, int flags);

}  // namespace kerf
