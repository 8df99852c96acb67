#pragma once

#include <array>
#include <cstdint>

#include "core/geometry/axes.h"

// Geometry of one path element, evaluated by arc length. Pure, noexcept, allocation-free: any
// thread, including RT.
namespace kerf::motion {

using AxisVector = std::array<double, kAxisCount>;
using Vec3Array = std::array<double, 3>;

// p(s) = origin + rate * s + radius * (cos(phi0 + k s) e1 + sin(phi0 + k s) e2)  (circle on XYZ)
// A line has radius 0; a circle or helix has its axial rise and the other axes in `rate`.
// s runs over [0, length] in mm of XYZ path (or in the units of the moving axes when only
// axes other than XYZ move).
struct PathGeometry {
    double length = 0.0;
    AxisVector origin{};
    AxisVector rate{};
    double radius = 0.0;
    double phi0 = 0.0;
    double k = 0.0;  // rad per unit s (> 0; e2 gives the turning direction)
    Vec3Array e1{};
    Vec3Array e2{};

    bool curved() const noexcept { return radius > 0.0; }
    // Curvature of the XYZ circle part: radius * k^2.
    double curvature() const noexcept { return radius * k * k; }
};

struct PathPoint {
    AxisVector position{};
    AxisVector tangent{};    // dp/ds
    AxisVector curvature{};  // d2p/ds2
};

AxisVector positionAt(const PathGeometry& g, double s) noexcept;
PathPoint pointAt(const PathGeometry& g, double s) noexcept;

PathGeometry makeLine(const AxisVector& from, const AxisVector& to) noexcept;

// Arc or helix from `from` about `center` (XYZ) in the plane with first/second/normal axes,
// signed sweep (positive counter-clockwise about the normal) ending at `to` (the normal axis
// and every other axis move linearly).
PathGeometry makeHelix(const AxisVector& from, const AxisVector& to, const Vec3Array& center,
                       Axis first, Axis second, Axis normal, double sweepRad) noexcept;

// Circular arc in XYZ from `from`, leaving along the unit `tangent`, ending at `to`; the other
// axes stay at `from`. Degenerates to a line when `to` lies on the tangent.
PathGeometry makeTangentArc(const AxisVector& from, const Vec3Array& tangent,
                            const AxisVector& to) noexcept;

// The same geometry with [s0, s1] of the original mapped onto [0, s1 - s0].
PathGeometry trimmed(const PathGeometry& g, double s0, double s1) noexcept;

// Distance from an XYZ point to the element's XYZ path over s in [s0, s1] (exact for lines and
// circles; for helices the distance of a point found by Newton steps from the planar angle, never
// less than the true distance).
double distanceTo(const PathGeometry& g, const Vec3Array& p, double s0, double s1) noexcept;

// Range of cos(phi - psi) for phi in [from, to] (from <= to).
struct CosRange {
    double lo = 0.0;
    double hi = 0.0;
};
CosRange cosRange(double from, double to, double psi) noexcept;

// Largest |component| over the element (bounds; exact for lines):
struct AxisBounds {
    AxisVector tangent{};        // |dp_i/ds|
    AxisVector curvature{};      // |d2p_i/ds2|
    AxisVector curvatureRate{};  // |d3p_i/ds3|
};
AxisBounds axisBounds(const PathGeometry& g) noexcept;

}  // namespace kerf::motion
