#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

namespace kerf::program {

// A large program's text kept out of the process's memory: an unnamed copy of the file, mapped
// read-only. The kernel drops its pages behind the reader and reads them again from the copy when
// a jump goes back, so a long program runs in a window of memory, not in a copy of its size. The
// copy has no name, so no other process can truncate or change it (a mapping of the file itself
// would die with SIGBUS when the file is truncated: docs/files.md).

// Files from this size on are copied and mapped; smaller ones are read into memory.
inline constexpr size_t kMappedCopyMinBytes = 4u << 20;
// How far a program's reader moves between two releases of the pages behind it.
inline constexpr size_t kTextReleaseStep = 1u << 20;

// Copies the regular file `file`, when it has kMappedCopyMinBytes or more, into an unnamed file
// in its folder and maps the copy. Nothing for a shorter file, one that is not regular, or when
// the folder's file system cannot hold an unnamed file or the copy fails: the caller reads the
// file into memory instead (part of the file-access layer, docs/files.md).
std::optional<std::string_view> mapUnnamedCopy(const std::filesystem::path& file);
void unmapCopy(std::string_view mapped);

// Lets the kernel drop the resident pages of `text` before `offset`; reading them again reads the
// copy. Does nothing when `text` is not in a mapped copy (a program read into memory).
void releasePagesBefore(std::string_view text, size_t offset);

}  // namespace kerf::program
