// The tool/profile analysis of G66/G68/G69 (spec part 2 §1.6) against hand-drawn profiles: the
// limits follow from the insert's angles (a 55° insert at CUTA 93° descends at most
// 180 - 93 - 55 = 32°) and its nose radius.
#include "core/cycles/lathe/tool_reach.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {
namespace {

// External turning towards -Z with the material below (towards the axis): the plane is (Z, X).
const Vec2 kFeed(-1.0, 0.0);
const Vec2 kOutward(0.0, 1.0);
const Vec2 kStart(0.0, 10.0);

ProfileElement lineTo(double z, double x) {
    ProfileElement e;
    e.end = Vec2(z, x);
    return e;
}

std::vector<ProfileElement> descentOf(double degrees) {
    // Flat for 10 mm, then down into the material at `degrees` for 10 mm along Z.
    return {lineTo(-10.0, 10.0), lineTo(-20.0, 10.0 - 10.0 * std::tan(degToRad(degrees)))};
}

TEST(ToolReach, DescentsUpToTheTrailingEdgeAngleAreReachable) {
    const InsertGeometry diamond55{93.0, 55.0, 0.4};
    EXPECT_FALSE(firstUnreachableElement(kStart, descentOf(30.0), kFeed, kOutward, diamond55));
    const auto steep = firstUnreachableElement(kStart, descentOf(35.0), kFeed, kOutward, diamond55);
    ASSERT_TRUE(steep);
    EXPECT_EQ(steep->kind, UnreachableElement::Kind::DescentTooSteep);
    EXPECT_EQ(steep->element, 1u);
    EXPECT_NEAR(steep->needed, 35.0, 1e-9);
    EXPECT_NEAR(steep->allowed, 32.0, 1e-9);
    // A 35° insert at the same CUTA leaves 52°.
    EXPECT_FALSE(firstUnreachableElement(kStart, descentOf(35.0), kFeed, kOutward,
                                         InsertGeometry{93.0, 35.0, 0.4}));
}

TEST(ToolReach, ShouldersSteeperThanTheLeadingEdgeAreNot) {
    // A shoulder straight up at Z-10: 90° from the feed.
    const std::vector<ProfileElement> shoulder{lineTo(-10.0, 10.0), lineTo(-10.0, 15.0),
                                               lineTo(-20.0, 15.0)};
    EXPECT_FALSE(firstUnreachableElement(kStart, shoulder, kFeed, kOutward, {93.0, 55.0, 0.4}));
    const auto wall = firstUnreachableElement(kStart, shoulder, kFeed, kOutward, {75.0, 55.0, 0.4});
    ASSERT_TRUE(wall);
    EXPECT_EQ(wall->kind, UnreachableElement::Kind::WallTooSteep);
    EXPECT_EQ(wall->element, 1u);
    EXPECT_NEAR(wall->needed, 90.0, 1e-9);
    EXPECT_NEAR(wall->allowed, 75.0, 1e-9);
}

TEST(ToolReach, ConcaveArcsSmallerThanTheNoseAreNotButConvexOnesAre) {
    // A concave fillet of radius 2 (centre Z-10 X12, above the path) up to a shoulder at Z-12,
    // then a convex round of radius 2 (centre Z-14 X12) down to X10 again... not: a convex round
    // over the top, from Z-12 X12 to Z-14 X14.
    ProfileElement fillet = lineTo(-12.0, 12.0);
    fillet.centre = Vec2(-10.0, 12.0);
    fillet.ccw = false;
    ProfileElement round = lineTo(-14.0, 14.0);
    round.centre = Vec2(-14.0, 12.0);
    round.ccw = true;
    const std::vector<ProfileElement> profile{lineTo(-10.0, 10.0), fillet, round,
                                              lineTo(-20.0, 14.0)};
    EXPECT_FALSE(firstUnreachableElement(kStart, profile, kFeed, kOutward, {93.0, 55.0, 1.2}));
    const auto tight = firstUnreachableElement(kStart, profile, kFeed, kOutward, {93.0, 55.0, 2.4});
    ASSERT_TRUE(tight);
    EXPECT_EQ(tight->kind, UnreachableElement::Kind::ArcTighterThanNose);
    EXPECT_EQ(tight->element, 1u);
    EXPECT_NEAR(tight->needed, 2.0, 1e-9);
}

TEST(ToolReach, UnknownGeometryChecksNothing) {
    EXPECT_FALSE(firstUnreachableElement(kStart, descentOf(80.0), kFeed, kOutward, {}));
}

}  // namespace
}  // namespace kerf::cycles::lathe
