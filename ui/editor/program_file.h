#pragma once

#include <QString>
#include <filesystem>

#include "core/base/expected.h"
#include "core/program/encoding.h"
#include "core/program/nc_root.h"

namespace kerf::ui {

// A program's text as the editor holds it (UTF-8, '\n' line ends) and how to write it back the
// way it was read: same encoding, same line ends.
struct ProgramText {
    QString text;
    program::Encoding encoding = program::Encoding::Utf8;
    bool crlf = false;
};

// An error for a file with a line longer than a block may be (program::kMaxBlockCharacters).
Expected<ProgramText> readProgramFile(const std::filesystem::path& path);
// Through the NC root's checks (docs/files.md): refused outside the root, through a link or onto
// something that is not a regular file. Atomic: a crash leaves the old file or the new one.
MaybeError writeProgramFile(const program::NcRoot& root, const std::filesystem::path& path,
                            const ProgramText& program);

}  // namespace kerf::ui
