#include "core/geometry/spatial_arc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace kerf {

std::vector<Vec3> arcChordPoints(const Vec3& from, const Vec3& to, const Vec3& centre,
                                 double tolerance) {
    const Vec3 a = from - centre;
    const Vec3 b = to - centre;
    const double radius = a.norm();
    const double sweep = std::atan2(a.cross(b).norm(), a.dot(b));
    if (radius <= 0.0 || sweep <= 0.0) return {to};
    // A chord over the angle s is r (1 - cos(s / 2)) from its arc at the middle.
    const double step =
        tolerance >= radius ? std::numbers::pi : 2.0 * std::acos(1.0 - tolerance / radius);
    const int pieces = std::max(1, static_cast<int>(std::ceil(sweep / step)));
    const Vec3 e1 = a / radius;
    const Vec3 e2 = (b - b.dot(e1) * e1).normalized();
    std::vector<Vec3> out;
    out.reserve(static_cast<size_t>(pieces));
    for (int i = 1; i < pieces; ++i) {
        const double angle = sweep * i / pieces;
        out.push_back(centre + radius * (std::cos(angle) * e1 + std::sin(angle) * e2));
    }
    out.push_back(to);
    return out;
}

}  // namespace kerf
