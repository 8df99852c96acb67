#include "motion/path/path_geometry.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"

namespace kerf::motion {
namespace {

AxisVector at(double x, double y, double z) {
    AxisVector p{};
    p[0] = x;
    p[1] = y;
    p[2] = z;
    return p;
}

// The distance by brute force: the element sampled every micrometre of arc length.
double sampledDistance(const PathGeometry& g, const Vec3Array& p) {
    double best = 1e300;
    const int steps = static_cast<int>(g.length / 1e-3) + 1;
    for (int i = 0; i <= steps; ++i) {
        AxisVector q = positionAt(g, g.length * i / steps);
        best =
            std::min(best, std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                     (p[2] - q[2]) * (p[2] - q[2])));
    }
    return best;
}

TEST(PathGeometry, DistanceToACircleIsRadialDistanceInsideTheSweep) {
    // Quarter circle of radius 10 about the origin from (10, 0) to (0, 10), counter-clockwise.
    PathGeometry g =
        makeHelix(at(10, 0, 0), at(0, 10, 0), {0, 0, 0}, Axis::X, Axis::Y, Axis::Z, kPi / 2);
    // At 45 degrees, 3 mm outside and 4 mm above: sqrt(3^2 + 4^2) = 5.
    const double c = std::sqrt(0.5);
    EXPECT_NEAR(distanceTo(g, {13 * c, 13 * c, 4}, 0.0, g.length), 5.0, 1e-12);
    // Outside the sweep the nearest point is the end (0, 10): from (-3, 10) that is 3 mm.
    EXPECT_NEAR(distanceTo(g, {-3, 10, 0}, 0.0, g.length), 3.0, 1e-12);
    // Only the first half of the sweep: the nearest point to (0, 12) is then at 45 degrees.
    EXPECT_NEAR(distanceTo(g, {0, 12, 0}, 0.0, g.length / 2), std::hypot(10 * c, 12 - 10 * c),
                1e-12);
}

TEST(PathGeometry, DistanceToHelicesAgreesWithDenseSampling) {
    // Two and a half turns of radius 3 rising 4 mm, clockwise, and points around it.
    PathGeometry g =
        makeHelix(at(3, 0, 0), at(-3, 0, 4), {0, 0, 0}, Axis::X, Axis::Y, Axis::Z, -2.5 * kTwoPi);
    for (int i = 0; i < 40; ++i) {
        const double a = 0.7 * i;
        const Vec3Array p{(3.0 + 0.05 * (i % 7) - 0.1) * std::cos(a),
                          (3.0 + 0.05 * (i % 7) - 0.1) * std::sin(a), -0.5 + 0.13 * i};
        const double exact = distanceTo(g, p, 0.0, g.length);
        const double sampled = sampledDistance(g, p);
        // Never less than the true distance, and within the sampling's own error.
        EXPECT_GE(exact, sampled - 1e-3) << i;
        EXPECT_LE(exact, sampled + 1e-9) << i;
    }
}

}  // namespace
}  // namespace kerf::motion
