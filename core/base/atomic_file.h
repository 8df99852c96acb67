#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/base/expected.h"

namespace kerf {

// Replaces `path` with `content` so that a crash leaves either the old or the new file, never a
// mix: the bytes go to a temporary file in the same folder, are flushed to disk, and the temporary
// file is renamed over the target.
MaybeError writeFileAtomically(const std::filesystem::path& path, std::string_view content);

// Reads a whole file into memory.
Expected<std::string> readWholeFile(const std::filesystem::path& path);

}  // namespace kerf
