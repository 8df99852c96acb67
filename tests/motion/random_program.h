#pragma once

#include <cstdint>
#include <vector>

#include "core/canon/commands.h"

// Random programs for invariant tests: lines of all lengths and directions, arcs and helices in
// the three planes, tangent and sharp joins, feeds from 100 to 15000 mm/min, rapid moves and
// changes of the path tolerance. Deterministic for a seed; stays within X, Y +-100 mm and
// Z -60 .. 40 mm.
namespace kerf::motion::test {

struct RandomProgramOptions {
    uint32_t seed = 1;
    int moves = 100;
    bool rapids = true;
    bool tolerances = true;
};

std::vector<canon::Command> randomProgram(const RandomProgramOptions& options);

}  // namespace kerf::motion::test
