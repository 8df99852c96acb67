#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

#include "core/base/expected.h"
#include "core/base/open_beneath.h"
#include "core/program/source_text.h"

namespace kerf::program {

// The folder that holds the NC programs and tables, and the file-access layer for it
// (docs/files.md). Programs may only name files inside it: `TNC:\dir\prog.h` and `\dir\prog.h`
// are relative to the root, other names to the calling program's folder; backslashes and forward
// slashes both separate folders.
//
// Every file a program, a table name or the HMI opens inside the root goes through admit(),
// read(), loadProgram() or replace() with the name actually opened (after extension fallbacks,
// for fixed table names too): containment is judged after every link is resolved, only regular
// files are read (a FIFO never blocks), and writes never go through a link and replace the file
// atomically.
class NcRoot {
public:
    explicit NcRoot(std::filesystem::path root);

    const std::filesystem::path& path() const { return m_root; }

    // The absolute path of `name`, or an error if it would leave the root.
    Expected<std::filesystem::path> resolve(std::string_view name,
                                            const std::filesystem::path& callerFolder) const;
    // True when `path`, with every link resolved (a dangling one too), lies inside the root.
    bool contains(const std::filesystem::path& path) const;

    // An error unless `finalPath` lies inside the root once its links are resolved.
    MaybeError admit(const std::filesystem::path& finalPath) const;
    // The bytes of a regular file inside the root.
    Expected<std::string> read(const std::filesystem::path& finalPath) const;
    // A program inside the root, copied into memory.
    Expected<std::shared_ptr<const SourceText>> loadProgram(
        const std::filesystem::path& finalPath) const;
    // An error unless `finalPath` may be written: inside the root, not a link, and a regular
    // file if it exists.
    MaybeError admitWrite(const std::filesystem::path& finalPath) const;
    // admitWrite(), then the file is replaced atomically (temporary file, fsync, rename).
    MaybeError replace(const std::filesystem::path& finalPath, std::string_view content) const;

private:
    Expected<FileDescriptor> openResolved(const std::filesystem::path& finalPath, int flags) const;

    std::filesystem::path m_root;
};

}  // namespace kerf::program
