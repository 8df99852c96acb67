#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/cycles/probing/manual_probing.h"

// The HTML logs the TNC writes without being asked (spec 1.15): TCHPRAUTO.html for the
// calibration cycles 460-463 (all calibrations of one program run in one file) and TCHPRMAN.html
// for Manual operation's probing functions. Lengths in mm, four decimals, no date (so that a run
// gives the same file every time).
namespace kerf::cycles::probing {

// One value a calibration determined: its name (R, L, CAL_OF1 ...), what the table held before
// and what it holds now.
struct CalibratedValue {
    std::string name;
    double before = 0.0;
    double after = 0.0;
};

struct CalibrationLogEntry {
    int cycle = 0;
    std::string cycleName;  // English, e.g. "CALIBRATE TS ON SPHERE"
    int tool = 0;
    int probe = 0;  // NO in tchprobe.tp
    std::vector<CalibratedValue> values;
};

std::string calibrationLogHtml(const std::string& program,
                               std::span<const CalibrationLogEntry> entries);

// The function, its touches (ball centres, directions, the surface points) and its result.
std::string manualProbingLogHtml(ManualProbingFunction function,
                                 std::span<const ManualTouch> touches, double ballRadius,
                                 const std::optional<ManualProbingResult>& result);

}  // namespace kerf::cycles::probing
