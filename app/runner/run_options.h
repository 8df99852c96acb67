#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/task/dry_run.h"

namespace kerf::app {

// What `kerf check` and `kerf run` were asked to do.
struct RunOptions {
    std::filesystem::path program;
    std::string machine = "mill";        // built-in name or TOML file
    std::optional<std::string> dialect;  // klartext, tnciso, fagor; default from the file
    std::optional<std::filesystem::path> toolTable;
    std::optional<std::filesystem::path> ncRoot;  // default: the program's folder
    std::optional<std::filesystem::path> reportFile;
    std::optional<std::filesystem::path> traceFile;  // "-" writes to standard output
    std::optional<std::filesystem::path> stateDir;   // where QR parameters are kept
    // Guard against endless loops: about two seconds of a tight loop (docs/headless.md).
    uint64_t maxBlocks = task::kDefaultMaxBlocks;
    bool blockSkip = false;
    // FAGOR user channel (app/runner/headless_operator.h, docs/headless.md): the program runs as
    // the customisation program of this mode (execution, edit, manual, diagnosis), answered by
    // the operator inputs in order (a key name for WKEY, a number for IB).
    std::optional<std::string> userScreen;
    std::vector<std::string> operatorInput;
    // Pictures and material removal (app/runner/picture_output.h, docs/graphics.md).
    std::optional<std::filesystem::path> png;
    std::optional<std::string> view;  // 3d, top, front, side, section
    std::optional<std::string> size;  // WIDTHxHEIGHT
    bool stock = false;
    // The drive chain (app/runner/drive_output.h, docs/drives.md): "can-sim" runs planner, servo
    // cycle, CANopen master and simulated drives on the virtual bus.
    std::optional<std::string> drives;
    std::optional<std::filesystem::path> canTrace;  // candump log of every frame
    std::vector<std::string> injectFaults;          // NODE:KIND@SECONDS
    double maxDriveTimeS = 3600.0;                  // simulated-time limit of the drive chain
    // Motion in simulated time (app/runner/motion_output.h, docs/motion.md); --samples implies it.
    bool motion = false;
    std::optional<std::filesystem::path> samples;  // CSV of every servo cycle's setpoints
    std::optional<double> emergencyStopAtS;        // simulated E-stop button, s after the start
    std::optional<std::string> workOffset;  // "X0,Y0,Z-300": workpiece origin, machine coords
    // The active preset: row n of PRESET.PR in the NC root (its axes and basic rotation SPC).
    std::optional<int> preset;
};

}  // namespace kerf::app
