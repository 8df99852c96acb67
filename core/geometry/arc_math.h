#pragma once

#include <cmath>
#include <optional>

#include "core/geometry/axes.h"

namespace kerf {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline double degToRad(double deg) {
    return deg * (kPi / 180.0);
}
inline double radToDeg(double rad) {
    return rad * (180.0 / kPi);
}

// The direction of v in degrees (-180, 180] from the abscissa, and the unit vector at an angle.
inline double angleDeg(const Vec2& v) {
    return radToDeg(std::atan2(v.y(), v.x()));
}
inline Vec2 unitAtDeg(double deg) {
    return {std::cos(degToRad(deg)), std::sin(degToRad(deg))};
}

inline double cross2(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}
// Left normal of a direction (rotated +90 degrees).
inline Vec2 leftNormal(const Vec2& d) {
    return {-d.y(), d.x()};
}

// Signed sweep in radians (positive counter-clockwise) from start to end around center. When start
// and end coincide the arc is a full circle (+-2 pi).
double arcSweep(const Vec2& start, const Vec2& end, const Vec2& center, bool ccw);

// Centre of the arc through start and end with the given radius and direction. A positive radius
// selects the arc of at most 180 degrees, a negative one the larger arc (TNC CR, Fagor G02/G03 R).
// Empty when the chord is longer than the diameter (beyond a small tolerance) or zero.
std::optional<Vec2> arcCenterFromRadius(const Vec2& start, const Vec2& end, double signedRadius,
                                        bool ccw);

struct TangentArc {
    Vec2 center;
    double sweep;  // signed radians
};
// Arc that leaves start along the unit direction `tangent` and ends at end (TNC CT, Fagor G08).
// Empty when end lies on the tangent line (the arc would degenerate into a line).
std::optional<TangentArc> tangentArc(const Vec2& start, const Vec2& tangent, const Vec2& end);

// Unit tangent of an arc at a point on it, in the direction of travel.
Vec2 arcTangentAt(const Vec2& center, const Vec2& point, double sweep);

struct Box2 {
    Vec2 min{1e300, 1e300};
    Vec2 max{-1e300, -1e300};
    void add(const Vec2& p) {
        min = min.cwiseMin(p);
        max = max.cwiseMax(p);
    }
};
// Adds the extreme points of the arc (start, end and every quadrant point it passes).
void addArcExtremes(Box2& box, const Vec2& center, const Vec2& start, double sweep);

// Circle through three points; empty if they are collinear.
struct Circle {
    Vec2 center;
    double radius;
};
std::optional<Circle> circleThrough(const Vec2& a, const Vec2& b, const Vec2& c);

}  // namespace kerf
