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

// A hole of unknown diameter (G5, 401, 416, 418, 430): four touches from its nominal centre, along
// +M, +S, -M, -S, each at most DIST; its centre from the circle through the ball centres.
std::optional<CycleError> probeHoleCentre(int cycle, ProbeSequence& sequence, const Vec2& nominal,
                                          Vec2& centre);

}  // namespace kerf::cycles::probing
