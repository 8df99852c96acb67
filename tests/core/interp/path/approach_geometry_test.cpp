#include "core/interp/path/approach_geometry.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf::interp {
namespace {

// Contour starting at the origin along +X, tool right of it (RR) with radius 5: the tool sits
// at (0,-5) on the contour start.
constexpr double kOffset = -5;

TEST(ApproachGeometry, TangentLine) {
    auto m = approachMoves(ApproachKind::Tangent, {-20, -20}, {0, 0}, {1, 0}, kOffset, 10, 0, 0);
    ASSERT_TRUE(m);
    ASSERT_EQ(m->size(), 2u);
    EXPECT_NEAR((*m)[0].end.x(), -10, 1e-12);
    EXPECT_NEAR((*m)[0].end.y(), -5, 1e-12);
    EXPECT_NEAR((*m)[1].end.y(), -5, 1e-12);
}

TEST(ApproachGeometry, CircleFromTheToolSide) {
    auto m = approachMoves(ApproachKind::Circle, {-20, -20}, {0, 0}, {1, 0}, kOffset, 0, 90, 10);
    ASSERT_TRUE(m);
    // Centre 10 below the contour point, tool circle radius 5, a clockwise quarter.
    EXPECT_NEAR((*m)[0].end.x(), -5, 1e-12);
    EXPECT_NEAR((*m)[0].end.y(), -10, 1e-12);
    EXPECT_TRUE((*m)[1].arc);
    EXPECT_NEAR((*m)[1].sweep, -M_PI / 2, 1e-12);
}

TEST(ApproachGeometry, LineIntoCircleIsTangentToTheLine) {
    auto m = approachMoves(ApproachKind::LineCircle, {-20, -20}, {0, 0}, {1, 0}, kOffset, 0, 0, 10);
    ASSERT_TRUE(m);
    const Vec2 touch = (*m)[0].end;
    const Vec2 center = (*m)[1].center;
    // The line from the start to the touch point is perpendicular to the radius there.
    EXPECT_NEAR((touch - Vec2(-20, -20)).dot(touch - center), 0, 1e-9);
    EXPECT_NEAR((touch - center).norm(), 5, 1e-12);
    // Start inside the circle: impossible.
    EXPECT_FALSE(
        approachMoves(ApproachKind::LineCircle, {0, -9}, {0, 0}, {1, 0}, kOffset, 0, 0, 10));
}

TEST(ApproachGeometry, DepartureNormal) {
    auto m = departureMoves(ApproachKind::Normal, {40, 30}, {0, 1}, kOffset, 12, 0, 0, Vec2(0, 0));
    ASSERT_TRUE(m);
    EXPECT_NEAR((*m)[0].end.x(), 57, 1e-12);
    EXPECT_NEAR((*m)[0].end.y(), 30, 1e-12);
}

}  // namespace
}  // namespace kerf::interp
