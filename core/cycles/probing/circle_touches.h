#pragma once

#include "core/cycles/probing/probe_geometry.h"
#include "core/cycles/probing/probe_sequence.h"

namespace kerf::cycles::probing {

// Touches on a circle (412, 413, 421, 422; spec 3 and G4): at the angles start + k * step,
// radially outward in a hole, inward on a stud.
struct CircleTouches {
    Vec2 centre{0.0, 0.0};
    double nominalDiameter = 0.0;
    double startAngleDeg = 0.0;
    double stepAngleDeg = 90.0;
    int count = 4;
    bool inside = true;
};

// The circle through the touched surface points.
std::optional<CycleError> probeCircle(int cycle, ProbeSequence& sequence,
                                      const CircleTouches& touches, FittedCircle& circle);

}  // namespace kerf::cycles::probing
