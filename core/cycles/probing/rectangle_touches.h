#pragma once

#include "core/cycles/probing/probe_sequence.h"

namespace kerf::cycles::probing {

// Touches at the middle of each side of a rectangle (410, 411, 423, 424): -M, +M, -S, +S,
// outward in a pocket, inward on a stud.
struct MeasuredRectangle {
    Vec2 centre{0.0, 0.0};
    Vec2 sides{0.0, 0.0};
};
std::optional<CycleError> probeRectangle(ProbeSequence& sequence, const Vec2& centre,
                                         const Vec2& sides, bool inside,
                                         MeasuredRectangle& measured);

}  // namespace kerf::cycles::probing
