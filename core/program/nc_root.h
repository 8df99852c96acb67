#pragma once

#include <filesystem>
#include <string_view>

#include "core/base/expected.h"

namespace kerf::program {

// The folder that holds the NC programs and tables. Programs may only name files inside it:
// `TNC:\dir\prog.h` and `\dir\prog.h` are relative to the root, other names to the calling
// program's folder; backslashes and forward slashes both separate folders.
class NcRoot {
public:
    explicit NcRoot(std::filesystem::path root);

    const std::filesystem::path& path() const { return m_root; }

    // The absolute path of `name`, or an error if it would leave the root.
    Expected<std::filesystem::path> resolve(std::string_view name,
                                            const std::filesystem::path& callerFolder) const;
    bool contains(const std::filesystem::path& path) const;

private:
    std::filesystem::path m_root;
};

}  // namespace kerf::program
