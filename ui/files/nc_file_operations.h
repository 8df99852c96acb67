#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/base/expected.h"
#include "core/program/nc_root.h"

namespace kerf::ui {

// File operations of the file manager, confined to the NC root: every source and target must
// lie inside it (links are followed before judging), the root itself cannot be renamed, moved or
// deleted, and protected files (no write permission, as the TNC's "protect" sets it) cannot be
// changed. Errors come back as diagnostics naming the file.
class NcFileOperations {
public:
    explicit NcFileOperations(std::filesystem::path root);

    const program::NcRoot& root() const { return m_root; }

    // Copies a file or folder into `targetFolder`, or to `target` when that is not a folder.
    Expected<std::filesystem::path> copy(const std::filesystem::path& source,
                                         const std::filesystem::path& target) const;
    Expected<std::filesystem::path> move(const std::filesystem::path& source,
                                         const std::filesystem::path& target) const;
    // New name in the same folder; the name may not contain folder separators.
    Expected<std::filesystem::path> rename(const std::filesystem::path& source,
                                           std::string_view newName) const;
    MaybeError remove(const std::filesystem::path& path) const;
    Expected<std::filesystem::path> makeFolder(const std::filesystem::path& parent,
                                               std::string_view name) const;
    // A new file `name` in `folder` with `content`, written through the NC root (atomic, never
    // through a link); refused when a file of that name exists.
    Expected<std::filesystem::path> createFile(const std::filesystem::path& folder,
                                               std::string_view name,
                                               std::string_view content) const;

    MaybeError setProtected(const std::filesystem::path& path, bool on) const;
    static bool isProtected(const std::filesystem::path& path);

private:
    MaybeError requireInside(const std::filesystem::path& path) const;
    MaybeError requireChangeable(const std::filesystem::path& path) const;
    // Where `source` goes for a copy or move to `target` (into it when it is a folder).
    Expected<std::filesystem::path> destination(const std::filesystem::path& source,
                                                const std::filesystem::path& target) const;

    program::NcRoot m_root;
};

}  // namespace kerf::ui
