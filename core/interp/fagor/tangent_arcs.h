#pragma once

#include <optional>

#include "core/geometry/arc_math.h"

namespace kerf::fagor {

// An arc of a tangential entry or exit: it meets the straight part at `tangentPoint`.
struct TangentArc {
    Vec2 tangentPoint;
    Vec2 center;
    double sweep = 0.0;  // signed radians
};

// G37: from `start` a straight line, then an arc of `radius` that reaches `contourPoint` moving
// along `tangent` (the direction of the next element there). Of the two circles tangent to the
// next element at the contour point, the one with the shorter arc; empty if `start` lies inside
// both (spec part 1 §9.7).
std::optional<TangentArc> tangentialEntry(const Vec2& start, const Vec2& contourPoint,
                                          const Vec2& tangent, double radius);

// G38: from `contourPoint`, where the last element ends moving along `tangent`, an arc of `radius`
// and then a straight line to `end`. The arc runs from the contour point to `tangentPoint`.
std::optional<TangentArc> tangentialExit(const Vec2& contourPoint, const Vec2& tangent,
                                         const Vec2& end, double radius);

}  // namespace kerf::fagor
