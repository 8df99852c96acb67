#include "core/geometry/contour_element.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf {
namespace {

Pose at(double x, double y, double z = 0) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

TEST(ContourElement, LineOffsetsToTheLeft) {
    auto line = ContourElement::line(Plane::XY, at(0, 0), at(10, 0));
    auto left = offsetElement(line, 2);
    ASSERT_TRUE(left);
    EXPECT_NEAR(left->start[Axis::Y], 2, 1e-12);
    EXPECT_NEAR(left->end[Axis::X], 10, 1e-12);
}

TEST(ContourElement, ArcOffsetChangesRadiusByDirection) {
    // CCW arc radius 10: its left is the centre side, so an offset of +2 gives radius 8.
    auto ccw = ContourElement::arc(Plane::XY, at(10, 0), at(0, 10), {0, 0}, kPi / 2);
    auto inner = offsetElement(ccw, 2);
    ASSERT_TRUE(inner);
    EXPECT_NEAR(inner->radius(), 8, 1e-12);
    auto cw = ContourElement::arc(Plane::XY, at(0, 10), at(10, 0), {0, 0}, -kPi / 2);
    EXPECT_NEAR(offsetElement(cw, 2)->radius(), 12, 1e-12);
    EXPECT_FALSE(offsetElement(ccw, 10));  // shrinks to nothing
}

TEST(ContourElement, HelixLengthAndAxisInterpolation) {
    auto helix = ContourElement::arc(Plane::XY, at(10, 0, 0), at(10, 0, -4), {0, 0}, 4 * kPi);
    EXPECT_NEAR(helix.planarLength(), 40 * kPi, 1e-9);
    Pose half = helix.poseAt(0.5);
    EXPECT_NEAR(half[Axis::Z], -2, 1e-12);
    EXPECT_NEAR(half[Axis::X], 10, 1e-9);  // two full turns: back at the start angle
}

TEST(ContourElement, ParamOfPointsBeforeAndAfter) {
    auto arc = ContourElement::arc(Plane::XY, at(10, 0), at(0, 10), {0, 0}, kPi / 2);
    EXPECT_NEAR(arc.paramOf({std::cos(kPi / 4) * 10, std::sin(kPi / 4) * 10}), 0.5, 1e-12);
    EXPECT_LT(arc.paramOf({10 * std::cos(-0.1), 10 * std::sin(-0.1)}), 0.0);
    EXPECT_GT(arc.paramOf({10 * std::cos(kPi / 2 + 0.1), 10 * std::sin(kPi / 2 + 0.1)}), 1.0);
}

TEST(ContourElement, IntersectionsOfCarriers) {
    auto a = ContourElement::line(Plane::XY, at(0, 5), at(10, 5));
    auto b = ContourElement::line(Plane::XY, at(3, 0), at(3, 1));
    auto ab = intersectCarriers(a, b);
    ASSERT_EQ(ab.size(), 1u);
    EXPECT_NEAR(ab[0].x(), 3, 1e-12);
    EXPECT_NEAR(ab[0].y(), 5, 1e-12);
    auto circle = ContourElement::arc(Plane::XY, at(10, 0), at(10, 0), {0, 0}, 2 * kPi);
    auto lc = intersectCarriers(a, circle);  // y = 5 cuts the circle r = 10 at x = +-8.660
    ASSERT_EQ(lc.size(), 2u);
    EXPECT_NEAR(std::fabs(lc[0].x()), std::sqrt(75.0), 1e-12);
    auto other = ContourElement::arc(Plane::XY, at(20, 0), at(20, 0), {10, 0}, 2 * kPi);
    auto cc = intersectCarriers(circle, other);  // r 10 at 0 and r 10 at 10: x = 5
    ASSERT_EQ(cc.size(), 2u);
    EXPECT_NEAR(cc[0].x(), 5, 1e-12);
}

TEST(Fillet, BetweenPerpendicularLines) {
    auto a = ContourElement::line(Plane::XY, at(0, 0), at(20, 0));
    auto b = ContourElement::line(Plane::XY, at(20, 0), at(20, 20));
    auto f = fillet(a, b, 5);
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->center.x(), 15, 1e-12);
    EXPECT_NEAR(f->center.y(), 5, 1e-12);
    EXPECT_NEAR(f->paramOnA, 0.75, 1e-12);
    EXPECT_NEAR(f->paramOnB, 0.25, 1e-12);
    EXPECT_NEAR(f->sweep, kPi / 2, 1e-12);
    EXPECT_FALSE(fillet(a, b, 25));  // does not fit
}

TEST(Fillet, BetweenLineAndArc) {
    // Line along +X to (10,0), then a CCW arc of radius 10 around (20,0) heading -Y: a right turn.
    // The rounding centre is 2 from both: on y = -2 and on the circle of radius 12, nearest the
    // corner: x = 20 - sqrt(144 - 4).
    auto a = ContourElement::line(Plane::XY, at(0, 0), at(10, 0));
    auto b = ContourElement::arc(Plane::XY, at(10, 0), at(20, -10), {20, 0}, kPi / 2);
    auto f = fillet(a, b, 2);
    ASSERT_TRUE(f);
    const double cx = 20 - std::sqrt(140.0);
    EXPECT_NEAR(f->center.x(), cx, 1e-9);
    EXPECT_NEAR(f->center.y(), -2, 1e-9);
    EXPECT_NEAR(f->paramOnA, cx / 10, 1e-9);
    // The arc is touched where the direction from (20,0) to the centre meets it: at an angle
    // asin(2/12) past the start, measured from the centre (20,0).
    const double travelled = std::asin(2.0 / 12.0);
    EXPECT_NEAR(f->paramOnB, travelled / (kPi / 2), 1e-9);
    EXPECT_NEAR(f->sweep, -(kPi / 2 - travelled), 1e-9);
}

}  // namespace
}  // namespace kerf
