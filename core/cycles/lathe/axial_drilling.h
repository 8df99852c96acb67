#pragma once

#include "core/cycles/lathe/lathe_path.h"

namespace kerf::cycles::lathe {

// G83: peck drilling (B > 0) or tapping (B = 0) along Z at (Z, X): spec part 2 §2 G83.
struct AxialHole {
    Vec2 start{0.0, 0.0};  // (z, x radius)
    double depth = 0.0;    // I: > 0 towards -Z
    double peck = 0.0;     // B, 0: tapping
    double safety = 0.0;   // D
    double dwellSeconds = 0.0;
    double retract = 0.0;        // H, 0: back to the approach point
    double reapproach = 1.0;     // C
    double minimumPeck = 0.0;    // L
    double factor = 1.0;         // R when drilling
    int tappingType = 0;         // R when tapping: 0 compensating holder, 1 rigid with M19, 2 rigid
    double tappingLeadMm = 0.0;  // rigid tapping: the feed per revolution
};

bool expandAxialHole(const AxialHole& hole, LathePath& path, LatheError& error);

}  // namespace kerf::cycles::lathe
