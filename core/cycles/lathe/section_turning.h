#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/cycles/lathe/lathe_path.h"

namespace kerf::cycles::lathe {

// One element of a turned profile, from the end of the previous one (z, x radius): a line, or an
// arc about `centre`, counter-clockwise in (z, x) if `ccw`.
struct ProfileElement {
    Vec2 end{0.0, 0.0};
    std::optional<Vec2> centre;
    bool ccw = false;
    uint32_t line = 0;  // the program line it comes from, for messages (0: none)
};

// The raw-stock profile of G66/G68/G69 (spec part 2 §1.6): the blank's outline, from `start`.
// Only the material between it and the finished profile is cut; where a pass runs outside it, it
// runs at rapid.
struct RawStock {
    Vec2 start{0.0, 0.0};
    std::vector<ProfileElement> elements;  // empty: no raw-stock profile
};

// Straight passes over a profile that grows steadily away from the call point: G81/G84 and G68
// (turning: passes along Z, stepping in X) and G82/G85 and G69 (facing: passes along X, stepping
// in Z). G81-G85 have one element, A -> B; spec part 2 §2, retract model §1.7.
struct TurningSection {
    bool facing = false;   // G82, G85, G69
    Vec2 start{0.0, 0.0};  // A (z, x radius)
    std::vector<ProfileElement> elements;
    double maxStep = 1.0;            // C
    std::optional<double> retract;   // D: absent, 0 or a safety distance
    double allowanceX = 0.0;         // L, radius
    double allowanceZ = 0.0;         // M
    bool channels = false;           // G68/G69: the profile may dip back into the material
    double roughingFeed = 0.0;       // the passes (0: the feed active at the call)
    double plungeFeed = 0.0;         // K: down into channels (0: the roughing feed)
    RawStock raw;                    // G68/G69
    double finalRoughingFeed = 0.0;  // F, 0: no final roughing pass
    double finishingFeed = 0.0;      // H, 0: no finishing pass
    double radiusTolerance = 0.01;   // mm: an arc's start and end radii may differ this much
};

// G84/G85: the arc of at most half a turn from a to b about `centre`.
bool shortArcIsCcw(const Vec2& a, const Vec2& b, const Vec2& centre);

// The passes from the call point `call`; false with `error` set if the call point or the profile
// do not allow the cycle.
bool expandTurningSection(const TurningSection& section, const Vec2& call, LathePath& path,
                          LatheError& error);

}  // namespace kerf::cycles::lathe
