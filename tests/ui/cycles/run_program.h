#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/base/diagnostic.h"

namespace kerf::ui::test {

// What running a Klartext program on the simulated mill gave: the diagnostics (empty when it
// ran to its end) and the tool-axis coordinate and X, Y of every feed move. Kept apart from the Qt
// test files: Qt's `emit` macro collides with the interpreter's emit().
struct ProgramRun {
    DiagnosticList diagnostics;
    bool finished = false;
    std::vector<double> feedZ;
    std::vector<std::array<double, 2>> feedXY;
};

ProgramRun runKlartextProgram(const std::string& text);
// The same for a TNC DIN/ISO program.
ProgramRun runIsoProgram(const std::string& text);

}  // namespace kerf::ui::test
