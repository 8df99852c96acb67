// Straight pieces of an arc in space against the arc's radius, plane and sagitta by hand.
#include "core/geometry/spatial_arc.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf {
namespace {

// A vertical quarter arc of radius 4 in the plane through (10, 20) along (0.6, 0.8): from 4 back
// along that direction at the centre's height down to 4 below the centre. Tolerance 0.5 µm:
// a chord over the angle s strays r (1 - cos(s / 2)) from the arc, so s <= 2 acos(1 - 1.25e-4)
// = 0.0316228 and the quarter needs ceil(1.5707963 / 0.0316228) = ceil(49.67) = 50 pieces,
// each over pi / 100 and straying 4 (1 - cos(pi / 200)) = 0.493 µm.
TEST(SpatialArc, ChordsOfAVerticalQuarterArcStayWithinTheTolerance) {
    const Vec3 centre(10.0, 20.0, 3.0);
    const Vec3 along(0.6, 0.8, 0.0);
    const Vec3 from = centre - 4.0 * along;
    const Vec3 to = centre - Vec3(0.0, 0.0, 4.0);
    const std::vector<Vec3> points = arcChordPoints(from, to, centre, 0.5e-3);
    ASSERT_EQ(points.size(), 50u);
    EXPECT_EQ(points.back(), to);
    const Vec3 normal(0.8, -0.6, 0.0);
    Vec3 previous = from;
    double worst = 0.0;
    for (const Vec3& p : points) {
        EXPECT_NEAR((p - centre).norm(), 4.0, 1e-12);
        EXPECT_NEAR((p - centre).dot(normal), 0.0, 1e-12);
        worst = std::max(worst, 4.0 - (0.5 * (p + previous) - centre).norm());
        previous = p;
    }
    EXPECT_NEAR(worst, 4.0 * (1.0 - std::cos(std::acos(-1.0) / 200.0)), 1e-12);
    EXPECT_LE(worst, 0.5e-3);
}

}  // namespace
}  // namespace kerf
