#pragma once

#include <optional>

#include "core/cycles/lathe/lathe_path.h"

namespace kerf::cycles::lathe {

// G86 (longitudinal: cut along Z, depth in X) and G87 (face: cut along X, depth in Z) threads,
// spec part 2 §2 G86, G87. Lengths in mm, X values as radii.
struct Thread {
    bool face = false;                 // G87
    Vec2 start{0.0, 0.0};              // (z, x) X Z
    Vec2 end{0.0, 0.0};                // Q R
    std::optional<double> measuredAt;  // K: along the cut axis, with W: thread repass
    double depth = 0.0;                // I: > 0 external (G86) or towards -Z (G87)
    double infeed = 0.0;               // B: > 0 B*sqrt(n), < 0 n*|B|
    double minimumIncrement = 0.0;     // E
    double safety = 0.0;               // D: > 0 round corners (G05) on the return, < 0 square
    double finishing = 0.0;            // L: > 0 along A, < 0 radial, 0 spring pass
    double pitch = 0.0;                // C: > 0 along the thread line, < 0 along the cut axis
    double exit = 0.0;                 // J
    double infeedAngleDeg = 30.0;      // A: < 0 zig-zag
    double spindleAngleDeg = 0.0;      // W
    int starts = 1;                    // V
    double pitchChange = 0.0;          // M, per revolution
};

bool expandThread(const Thread& thread, const Vec2& call, LathePath& path, LatheError& error);

}  // namespace kerf::cycles::lathe
