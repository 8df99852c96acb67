#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/cycles/lathe/section_turning.h"

namespace kerf::cycles::lathe {

// The insert of a turning tool as the FAGOR geometry table describes it (spec part 2 §1.6):
// CUTA, the angle of the leading (main) edge from the feed direction, and NOSEA, the angle
// between the two edges; the nose radius R of the tool offset. The trailing edge therefore lies
// CUTA + NOSEA from the feed direction.
struct InsertGeometry {
    double cuttingAngleDeg = 0.0;  // CUTA
    double noseAngleDeg = 0.0;     // NOSEA
    double noseRadius = 0.0;       // R
};

// Why the insert cannot follow an element of the profile.
struct UnreachableElement {
    enum class Kind { WallTooSteep, DescentTooSteep, ArcTighterThanNose };
    Kind kind = Kind::WallTooSteep;
    size_t element = 0;    // index in the profile
    double needed = 0.0;   // degrees (walls, descents) or the arc's radius
    double allowed = 0.0;  // what the insert allows, same unit
};

// The tool/profile analysis of G66/G68/G69: the first element of the profile from `start` that
// the insert cannot follow while the cycle feeds along `feed` (a unit vector of the plane) with
// the material on the side opposite `outward` (unit, perpendicular to `feed`): a wall rising
// towards `outward` steeper than CUTA, a descent into the material steeper than
// 180° - CUTA - NOSEA, or a concave arc of a smaller radius than the nose. Empty when every
// element is reachable; without CUTA or NOSEA only the arcs are checked.
std::optional<UnreachableElement> firstUnreachableElement(
    const Vec2& start, const std::vector<ProfileElement>& profile, const Vec2& feed,
    const Vec2& outward, const InsertGeometry& insert);

}  // namespace kerf::cycles::lathe
