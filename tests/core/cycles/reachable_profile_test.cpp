// The modified profile of G66/G68/G69 (spec part 2 §1.6) against hand-drawn valleys: a 55°
// insert at CUTA 93° descends at most 180 - 93 - 55 = 32°, so a steeper valley wall is bridged
// by the 32° line from where the descent starts to where it meets the profile again.
#include "core/cycles/lathe/reachable_profile.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {
namespace {

// External turning towards -Z with the material below (towards the axis): the plane is (Z, X).
const Vec2 kFeed(-1.0, 0.0);
const Vec2 kOutward(0.0, 1.0);
const InsertGeometry kInsert{93.0, 55.0, 0.4};

ProfileElement lineTo(double z, double x) {
    ProfileElement e;
    e.end = Vec2(z, x);
    return e;
}

void expectPoint(const Vec2& p, double z, double x) {
    EXPECT_NEAR(p.x(), z, 1e-6);
    EXPECT_NEAR(p.y(), x, 1e-6);
}

TEST(ReachableProfile, AVGrooveIsBridgedAtTheSteepestDescent) {
    // r20 to Z-10, down to r10 at Z-15 (63°), up to r20 at Z-20, on to Z-40. The bridge
    // x = 20 - (d - 10) t (d = -z, t = tan 32°) meets the rising wall x = 10 + 2 (d - 15)
    // at d = (40 + 10 t) / (2 + t).
    const std::vector<ProfileElement> profile{lineTo(-10, 20), lineTo(-15, 10), lineTo(-20, 20),
                                              lineTo(-40, 20)};
    const auto reached = reachableProfile(Vec2(0, 20), profile, kFeed, kOutward, kInsert);
    const double t = std::tan(degToRad(32.0));
    const double d = (40.0 + 10.0 * t) / (2.0 + t);
    ASSERT_EQ(reached.size(), 4u);
    expectPoint(reached[0].end, -10, 20);
    expectPoint(reached[1].end, -d, 20 - (d - 10) * t);
    EXPECT_FALSE(reached[1].centre);
    expectPoint(reached[2].end, -20, 20);
    expectPoint(reached[3].end, -40, 20);
}

TEST(ReachableProfile, ARoundValleyKeepsTheRestOfItsArc) {
    // A half circle of radius 5 about (Z-15, r20) down into the material. The 32° line from
    // Z-10 meets the circle where the angle at the centre is 2 * 32° from the far end: a point
    // 5 cos 64° beyond the centre along -Z, 5 sin 64° below it.
    ProfileElement arc;
    arc.end = Vec2(-20, 20);
    arc.centre = Vec2(-15, 20);
    arc.ccw = false;  // from Z-10 through r15 to Z-20: clockwise in (z, x)
    const std::vector<ProfileElement> profile{lineTo(-10, 20), arc, lineTo(-30, 20)};
    const auto reached = reachableProfile(Vec2(0, 20), profile, kFeed, kOutward, kInsert);
    const double a = degToRad(64.0);
    ASSERT_EQ(reached.size(), 4u);
    expectPoint(reached[0].end, -10, 20);
    expectPoint(reached[1].end, -15 - 5 * std::cos(a), 20 - 5 * std::sin(a));
    EXPECT_FALSE(reached[1].centre);
    ASSERT_TRUE(reached[2].centre);
    expectPoint(*reached[2].centre, -15, 20);
    EXPECT_FALSE(reached[2].ccw);
    expectPoint(reached[2].end, -20, 20);
    expectPoint(reached[3].end, -30, 20);
}

TEST(ReachableProfile, ReachableProfilesAndUnknownInsertsStayAsTheyAre) {
    // A 30° descent is within 32°; without NOSEA nothing is known.
    const double drop = 10.0 * std::tan(degToRad(30.0));
    const std::vector<ProfileElement> gentle{lineTo(-10, 20), lineTo(-20, 20 - drop),
                                             lineTo(-30, 20 - drop)};
    const auto same = reachableProfile(Vec2(0, 20), gentle, kFeed, kOutward, kInsert);
    ASSERT_EQ(same.size(), 3u);
    expectPoint(same[1].end, -20, 20 - drop);
    const std::vector<ProfileElement> groove{lineTo(-10, 20), lineTo(-10, 10), lineTo(-20, 10),
                                             lineTo(-20, 20)};
    EXPECT_EQ(reachableProfile(Vec2(0, 20), groove, kFeed, kOutward, {93.0, 0.0, 0.4}).size(), 4u);
}

TEST(ReachableProfile, ASquareGrooveEndsUnderTheBridgeWhenTheProfileEndsInIt) {
    // A vertical drop at Z-10 to r10 and the profile ends at Z-20 still on r10: the bridge runs
    // from (Z-10, r20) at 32° down to above the end, x = 20 - 10 tan 32°.
    const std::vector<ProfileElement> profile{lineTo(-10, 20), lineTo(-10, 10), lineTo(-20, 10)};
    const auto reached = reachableProfile(Vec2(0, 20), profile, kFeed, kOutward, kInsert);
    ASSERT_EQ(reached.size(), 2u);
    expectPoint(reached[1].end, -20, 20 - 10 * std::tan(degToRad(32.0)));
}

TEST(ReachableProfile, ALeadingEdgeBelowNinetyDegreesBridgesRisingWalls) {
    // CUTA 60°, NOSEA 35°: descents up to 85° pass, the vertical rise at Z-20 does not: from
    // its top (Z-20, r20) the 60° line back meets the floor r10 at Z-20 + 10 / tan 60°.
    const std::vector<ProfileElement> profile{lineTo(-10, 20), lineTo(-10, 10), lineTo(-20, 10),
                                              lineTo(-20, 20), lineTo(-30, 20)};
    const auto reached = reachableProfile(Vec2(0, 20), profile, kFeed, kOutward, {60.0, 35.0, 0.4});
    // The vertical drop at Z-10 (90°) is steeper than 85° as well: bridged at 85° to the floor.
    const double t85 = std::tan(degToRad(85.0));
    ASSERT_EQ(reached.size(), 5u);
    expectPoint(reached[1].end, -10 - 10 / t85, 10);
    expectPoint(reached[2].end, -20 + 10 / std::tan(degToRad(60.0)), 10);
    expectPoint(reached[3].end, -20, 20);
    expectPoint(reached[4].end, -30, 20);
}

ProfileElement arcTo(double z, double x, double cz, double cx, bool ccw, uint32_t line = 0) {
    ProfileElement e;
    e.end = Vec2(z, x);
    e.centre = Vec2(cz, cx);
    e.ccw = ccw;
    e.line = line;
    return e;
}

TEST(ReachableProfile, ACoveTighterThanTheNoseIsLeftWhereTheNoseStops) {
    // A half-round cove of radius 1 (centre Z-11 r20) in r20, nose R1.5: the nose rests on the
    // cove's edges (Z-10, r20) and (Z-12, r20) with its centre sqrt(1.5^2 - 1^2) above r20 and
    // dips to r20 + sqrt(1.25) - 1.5; the profile there is that arc of the nose, clockwise, in
    // place of the cove (line 7). No angle data: only the nose counts.
    const std::vector<ProfileElement> profile{lineTo(-10, 20), arcTo(-12, 20, -11, 20, false, 7),
                                              lineTo(-30, 20)};
    for (const InsertGeometry& insert :
         {InsertGeometry{0.0, 0.0, 1.5}, InsertGeometry{93.0, 35.0, 1.5}}) {
        const auto reached = reachableProfile(Vec2(0, 20), profile, kFeed, kOutward, insert);
        ASSERT_EQ(reached.size(), 3u);
        expectPoint(reached[0].end, -10, 20);
        ASSERT_TRUE(reached[1].centre);
        expectPoint(*reached[1].centre, -11, 20 + std::sqrt(1.25));
        EXPECT_FALSE(reached[1].ccw);
        expectPoint(reached[1].end, -12, 20);
        EXPECT_EQ(reached[1].line, 7u);
        expectPoint(reached[2].end, -30, 20);
    }
    // A nose of R1 fits the cove: nothing changes.
    const auto fits = reachableProfile(Vec2(0, 20), profile, kFeed, kOutward, {0.0, 0.0, 1.0});
    ASSERT_EQ(fits.size(), 3u);
    expectPoint(*fits[1].centre, -11, 20);
}

TEST(ReachableProfile, ATightFilletAtAShoulderBecomesTheNosesRadius) {
    // r10 to Z-20, a concave fillet R1 (centre Z-21 r11... no: centre (Z-19, r11)) up to the
    // shoulder face Z-20 at r11... Written as: r10 to Z-19, fillet R1 about (Z-19, r11) to
    // (Z-20, r11), the face up to r20, r20 to Z-30. Nose R2: the nose touches the diameter and
    // the face with its centre at (Z-18, r12); the fillet becomes R2 about it, from (Z-18, r10)
    // to (Z-20, r12), tangent to both.
    const std::vector<ProfileElement> profile{lineTo(-19, 10), arcTo(-20, 11, -19, 11, false, 7),
                                              lineTo(-20, 20), lineTo(-30, 20)};
    const auto reached = reachableProfile(Vec2(0, 10), profile, kFeed, kOutward, {0.0, 0.0, 2.0});
    ASSERT_EQ(reached.size(), 4u);
    expectPoint(reached[0].end, -18, 10);
    ASSERT_TRUE(reached[1].centre);
    expectPoint(*reached[1].centre, -18, 12);
    EXPECT_FALSE(reached[1].ccw);
    expectPoint(reached[1].end, -20, 12);
    EXPECT_EQ(reached[1].line, 7u);
    expectPoint(reached[2].end, -20, 20);
    expectPoint(reached[3].end, -30, 20);
}

}  // namespace
}  // namespace kerf::cycles::lathe
