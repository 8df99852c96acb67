#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace kerf::app {

// What `kerf check` and `kerf run` were asked to do.
struct RunOptions {
    std::filesystem::path program;
    std::string machine = "mill";         // built-in name or TOML file
    std::optional<std::string> dialect;   // klartext, tnciso, fagor; default from the file
    std::optional<std::filesystem::path> toolTable;
    std::optional<std::filesystem::path> ncRoot;  // default: the program's folder
    std::optional<std::filesystem::path> reportFile;
    std::optional<std::filesystem::path> traceFile;  // "-" writes to standard output
    std::optional<std::filesystem::path> stateDir;   // where QR parameters are kept
    uint64_t maxBlocks = 2'000'000'000;  // guard against endless loops
    bool blockSkip = false;
};

}  // namespace kerf::app
