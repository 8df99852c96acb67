#pragma once

#include <optional>
#include <vector>

#include "core/cycles/cycle_context.h"
#include "core/cycles/pattern/pattern_plan.h"

namespace kerf::cycles {

// One element of a PATTERN DEF block, e.g. "PAT1 (X+25 Y+33.5 DX+8 DY+10 NUMX5 NUMY4 ...)".
struct PatternElement {
    enum class Kind : uint8_t { Pos, Row, Pat, Frame, Circ, PitchCirc };
    struct Word {
        double value = 0.0;
        bool incremental = false;
        bool present = false;
    };
    Kind kind = Kind::Pos;
    int index = 1;
    Word x, y, z, d, dx, dy, num, numX, numY, rot, rotX, rotY, start, step;
};

// The machining positions of a PATTERN DEF in definition order (spec 1.8): POS points (IX/IY/IZ
// relative to the previous one), ROW, PAT and FRAME row by row, each row along the main axis
// direction, CIRC and PITCHCIRC from START. A non-zero Z replaces the cycle's surface Q203.
std::optional<CycleError> patternPoints(const std::vector<PatternElement>& elements,
                                        std::vector<PatternPoint>& points);

}  // namespace kerf::cycles
