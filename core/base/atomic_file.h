#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/base/expected.h"

namespace kerf {

// The low level of the file-access layer (docs/files.md); names inside the NC root go through
// program::NcRoot, which adds containment and refuses links.

// Replaces `path` with `content` so that a crash leaves either the old or the new file, never a
// mix: the bytes go to a temporary file in the same folder, are flushed to disk, and the temporary
// file is renamed over the target. A target that exists and is not a regular file (a FIFO, a
// device, a folder) is refused.
MaybeError writeFileAtomically(const std::filesystem::path& path, std::string_view content);
// The same inside an open folder: `fileName` is a plain name in `folderFd`, `path` names the file
// in messages. Whatever happens to the folder's path meanwhile, the file lands in that folder.
MaybeError writeFileAtomicallyAt(int folderFd, const std::string& fileName,
                                 const std::filesystem::path& path, std::string_view content);

// Reads a whole regular file into memory. Never blocks on a FIFO: anything but a regular file is
// refused with "not a regular file".
Expected<std::string> readWholeFile(const std::filesystem::path& path);
// The same for a file already open (opened with O_NONBLOCK); `path` names it in messages.
Expected<std::string> readOpenFile(int fd, const std::filesystem::path& path);

// The error for a name that is not a regular file.
Diagnostic notRegular(const std::filesystem::path& path);

// True when both names lead to the same existing file (same device and inode), whatever links,
// "..", or hard links are in between.
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace kerf
