#pragma once

#include <optional>
#include <vector>

#include "core/geometry/axes.h"

// The infinite line or full circle an FK element runs on, with its direction of travel, and the
// constructions the solver needs between such carriers.
namespace kerf::fk {

inline constexpr double kFkTolerance = 1e-6;

struct Carrier {
    bool circle = false;
    Vec2 point{0.0, 0.0};  // line: a point on it
    Vec2 dir{1.0, 0.0};    // line: unit direction of travel
    Vec2 centre{0.0, 0.0};
    double radius = 0.0;
    bool ccw = true;  // circle: direction of travel

    static Carrier line(const Vec2& point, const Vec2& dir);
    static Carrier arc(const Vec2& centre, double radius, bool ccw);

    // Unit direction of travel at a point of the carrier.
    Vec2 tangentAt(const Vec2& p) const;
    double distanceTo(const Vec2& p) const;
    bool contains(const Vec2& p) const { return distanceTo(p) <= kFkTolerance * scale(); }
    double scale() const;  // tolerance grows with the size of the numbers
    bool sameAs(const Carrier& other) const;
};

// Intersections, without duplicates (a touching pair gives one point).
std::vector<Vec2> intersect(const Carrier& a, const Carrier& b);

// Where two carriers touch with the same direction of travel (a tangential transition), if they
// do.
std::optional<Vec2> touchPoint(const Carrier& from, const Carrier& to);

// Points where a line through `from` touches the circle (centre, radius): none, one or two.
std::vector<Vec2> tangentPointsFrom(const Vec2& from, const Vec2& centre, double radius);

// Orders points along a line's direction, farthest first (the FK solutions' numbering).
void orderAlong(std::vector<Vec2>& points, const Vec2& dir);

}  // namespace kerf::fk
