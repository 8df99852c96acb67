#pragma once

#include <optional>

#include "core/cycles/lathe/lathe_path.h"

namespace kerf::cycles::lathe {

// G81/G84 (turning: passes along Z, stepping in X) and G82/G85 (facing: passes along X,
// stepping in Z) over the section A -> B, a line (G81, G82) or an arc about `centre` (G84, G85):
// spec part 2 §2 G81-G85, retract model §1.7.
struct TurningSection {
    bool facing = false;  // G82, G85
    Vec2 a{0.0, 0.0};     // (z, x radius)
    Vec2 b{0.0, 0.0};
    std::optional<Vec2> centre;      // the arc's centre (z, x radius); none: a line
    double maxStep = 1.0;            // C
    std::optional<double> retract;   // D: absent, 0 or a safety distance
    double allowanceX = 0.0;         // L, radius
    double allowanceZ = 0.0;         // M
    double finalRoughingFeed = 0.0;  // F, 0: no final roughing pass
    double finishingFeed = 0.0;      // H, 0: no finishing pass
    double radiusTolerance = 0.01;   // mm: |A - centre| and |B - centre| may differ this much
};

// The passes from the call point `call`; false with `error` set if the call point or the section
// do not allow the cycle.
bool expandTurningSection(const TurningSection& section, const Vec2& call, LathePath& path,
                          LatheError& error);

}  // namespace kerf::cycles::lathe
