#include "core/geometry/arc_math.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf {
namespace {

TEST(ArcSweep, QuarterCircleBothDirections) {
    const Vec2 c(0, 0), a(10, 0), b(0, 10);
    EXPECT_NEAR(arcSweep(a, b, c, true), kPi / 2, 1e-12);
    EXPECT_NEAR(arcSweep(a, b, c, false), -3 * kPi / 2, 1e-12);
}

TEST(ArcSweep, CoincidentEndsMakeFullCircles) {
    const Vec2 c(5, 5), a(15, 5);
    EXPECT_NEAR(arcSweep(a, a, c, true), 2 * kPi, 1e-12);
    EXPECT_NEAR(arcSweep(a, a, c, false), -2 * kPi, 1e-12);
}

TEST(ArcCenterFromRadius, SmallAndLargeArc) {
    // Chord from (0,0) to (20,0), radius 20: centre 17.3205 above or below the chord midpoint.
    const double h = std::sqrt(400.0 - 100.0);
    auto smallCcw = arcCenterFromRadius({0, 0}, {20, 0}, 20, true);
    ASSERT_TRUE(smallCcw);
    EXPECT_NEAR(smallCcw->x(), 10, 1e-12);
    EXPECT_NEAR(smallCcw->y(), h, 1e-12);  // CCW small arc: centre left of the chord
    auto largeCcw = arcCenterFromRadius({0, 0}, {20, 0}, -20, true);
    ASSERT_TRUE(largeCcw);
    EXPECT_NEAR(largeCcw->y(), -h, 1e-12);
    auto smallCw = arcCenterFromRadius({0, 0}, {20, 0}, 20, false);
    ASSERT_TRUE(smallCw);
    EXPECT_NEAR(smallCw->y(), -h, 1e-12);
}

TEST(ArcCenterFromRadius, ChordLongerThanDiameterFails) {
    EXPECT_FALSE(arcCenterFromRadius({0, 0}, {30, 0}, 10, true));
    // A hair longer than the diameter (rounded program values) is a half circle.
    auto half = arcCenterFromRadius({0, 0}, {20.0000001, 0}, 10, true);
    ASSERT_TRUE(half);
    EXPECT_NEAR(half->x(), 10, 1e-6);
}

TEST(TangentArc, QuarterCircleFromHorizontalTangent) {
    auto arc = tangentArc({10, 0}, {1, 0}, {20, 10});
    ASSERT_TRUE(arc);
    EXPECT_NEAR(arc->center.x(), 10, 1e-12);
    EXPECT_NEAR(arc->center.y(), 10, 1e-12);
    EXPECT_NEAR(arc->sweep, kPi / 2, 1e-12);
    EXPECT_FALSE(tangentArc({0, 0}, {1, 0}, {5, 0}));  // end on the tangent
}

TEST(ArcExtremes, CoversQuadrantPointsInsideTheSweep) {
    Box2 box;
    addArcExtremes(box, {0, 0}, {10, 0}, kPi);  // upper half circle
    EXPECT_NEAR(box.min.x(), -10, 1e-9);
    EXPECT_NEAR(box.max.x(), 10, 1e-9);
    EXPECT_NEAR(box.min.y(), 0, 1e-9);
    EXPECT_NEAR(box.max.y(), 10, 1e-9);
}

TEST(CircleThrough, ThreePoints) {
    auto c = circleThrough({15, 5}, {5, 15}, {-5, 5});
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->center.x(), 5, 1e-12);
    EXPECT_NEAR(c->center.y(), 5, 1e-12);
    EXPECT_NEAR(c->radius, 10, 1e-12);
    EXPECT_FALSE(circleThrough({0, 0}, {1, 1}, {2, 2}));
}

}  // namespace
}  // namespace kerf
