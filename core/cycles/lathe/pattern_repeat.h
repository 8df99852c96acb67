#pragma once

#include <optional>
#include <vector>

#include "core/cycles/lathe/lathe_path.h"
#include "core/cycles/lathe/section_turning.h"

namespace kerf::cycles::lathe {

// G66 pattern repeat (spec part 2 §2 G66): passes that copy the profile, for a blank that already
// has the part's shape (cast or forged).
struct PatternRepeat {
    Vec2 start{0.0, 0.0};  // X, Z of the cycle (z, x radius): where the profile starts
    std::vector<ProfileElement> elements;
    bool stockAlongZ = false;          // A1: I and C are measured along Z (A0: along X)
    double stock = 0.0;                // I
    double step = 1.0;                 // C
    double allowanceX = 0.0;           // |L|
    std::optional<double> allowanceZ;  // |M|; absent: |L| all round, the passes are offsets
    double finishingFeed = 0.0;        // H; 0: no finishing pass
    RawStock raw;                      // passes wholly outside it are left out
    double radiusTolerance = 0.01;     // mm: an arc's start and end radii may differ this much
};

// The passes from the call point `call`; false with `error` set if the call point or the profile
// do not allow the cycle.
bool expandPatternRepeat(const PatternRepeat& cycle, const Vec2& call, LathePath& path,
                         LatheError& error);

}  // namespace kerf::cycles::lathe
