#pragma once

#include <optional>
#include <span>

#include "core/geometry/axes.h"

namespace kerf::cycles::probing {

struct FittedCircle {
    Vec2 centre{0.0, 0.0};
    double radius = 0.0;
};

// The circle through three points, or the least-squares (Kasa) circle of more; exact when the
// points lie on one circle. Nothing when they are (nearly) collinear (spec 1.17 G4).
std::optional<FittedCircle> fitCircle(std::span<const Vec2> points);

// Touch points closer than this (the display's resolution) give a line no direction.
inline constexpr double kMinTouchDistanceMm = 0.001;

// Angle of the line from `a` to `b` to the main axis in degrees, (-180, 180] (G2); nothing when
// the points are closer than kMinTouchDistanceMm (atan2(0, 0) would make it 0).
std::optional<double> lineAngleDeg(const Vec2& a, const Vec2& b);
// Normalised to (-180, 180] (G7).
double normalizedDeg(double degrees);

// Intersection of the lines a1-a2 and b1-b2; nothing when they are parallel (G3, PRB-019) or
// the two points of a line coincide (lineAngleDeg).
std::optional<Vec2> intersect(const Vec2& a1, const Vec2& a2, const Vec2& b1, const Vec2& b2);

}  // namespace kerf::cycles::probing
