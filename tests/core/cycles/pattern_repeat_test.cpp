// G66 pattern repeat as a pure expansion: the passes of a shouldered profile derived by hand, and
// over random profiles every cut lies exactly at its pass's distance from the finished profile.
#include "core/cycles/lathe/pattern_repeat.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/geometry/offset_contour.h"

namespace kerf::cycles::lathe {
namespace {

using Kind = LatheStep::Kind;

ProfileElement lineTo(double z, double x) {
    return {Vec2(z, x), std::nullopt, false};
}

// r10 from the face Z0 to Z-20, a shoulder up to r20, r20 to Z-40; called from Z5 r40.
PatternRepeat shoulder() {
    PatternRepeat cycle;
    cycle.start = Vec2(0.0, 10.0);
    cycle.elements = {lineTo(-20.0, 10.0), lineTo(-20.0, 20.0), lineTo(-40.0, 20.0)};
    cycle.stock = 6.0;
    cycle.step = 2.0;
    cycle.allowanceX = 0.5;
    return cycle;
}

void expectStep(const LatheStep& step, Kind kind, double z, double x) {
    EXPECT_EQ(step.kind, kind);
    EXPECT_NEAR(step.to.x(), z, 1e-9);
    EXPECT_NEAR(step.to.y(), x, 1e-9);
}

TEST(PatternRepeat, ShoulderPassesAreOffsetsOfTheProfile) {
    // I6 C2 L0.5: passes 4, 2 and 0.5 from the profile (ceil(5.5 / 2) = 3). At distance d the
    // diameter r10 becomes r10+d up to the shoulder moved to Z-20+d, then the outer corner
    // (Z-20, r20) is rounded with radius d, then r20+d to Z-40.
    const Vec2 call(5.0, 40.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(shoulder(), call, path, error)) << error.messageTemplate;
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_EQ(s.size(), 3u * 7u + 0u);
    const double depths[] = {4.0, 2.0, 0.5};
    for (int k = 0; k < 3; ++k) {
        const double d = depths[k];
        const LatheStep* p = &s[static_cast<size_t>(7 * k)];
        expectStep(p[0], Kind::Rapid, 0.0, 10.0 + d);
        expectStep(p[1], Kind::Feed, -20.0 + d, 10.0 + d);
        expectStep(p[2], Kind::Feed, -20.0 + d, 20.0);
        expectStep(p[3], Kind::FeedArc, -20.0, 20.0 + d);
        EXPECT_NEAR(p[3].centre.x(), -20.0, 1e-9);
        EXPECT_NEAR(p[3].centre.y(), 20.0, 1e-9);
        EXPECT_TRUE(p[3].ccw);
        expectStep(p[4], Kind::Feed, -40.0, 20.0 + d);
        expectStep(p[5], Kind::Rapid, -40.0, 40.0);  // out along X first
        expectStep(p[6], Kind::Rapid, 5.0, 40.0);
        EXPECT_EQ(p[1].feed, 0.0);  // the feed active at the call
    }
}

TEST(PatternRepeat, PassesOutsideTheRawStockAreLeftOut) {
    // A casting 3 mm over the shoulder profile (r13 to Z-20, r23 to Z-40): the pass 4 out lies
    // wholly outside it and is left out; the passes 2 and 0.5 out cut it.
    PatternRepeat cycle = shoulder();
    cycle.raw.start = Vec2(0.0, 13.0);
    cycle.raw.elements = {lineTo(-20.0, 13.0), lineTo(-20.0, 23.0), lineTo(-40.0, 23.0)};
    const Vec2 call(5.0, 40.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error)) << error.messageTemplate;
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_EQ(s.size(), 2u * 7u);
    expectStep(s[0], Kind::Rapid, 0.0, 12.0);
    expectStep(s[7], Kind::Rapid, 0.0, 10.5);
}

TEST(PatternRepeat, FinishingPassFollowsTheProfileAtFeedH) {
    PatternRepeat cycle = shoulder();
    cycle.finishingFeed = 0.1;
    const Vec2 call(5.0, 40.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error));
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_EQ(s.size(), 3u * 7u + 6u);
    const LatheStep* f = &s[21];
    expectStep(f[0], Kind::Rapid, 0.0, 10.0);
    expectStep(f[1], Kind::Feed, -20.0, 10.0);
    expectStep(f[2], Kind::Feed, -20.0, 20.0);
    expectStep(f[3], Kind::Feed, -40.0, 20.0);
    EXPECT_EQ(f[3].feed, 0.1);
    expectStep(f[4], Kind::Rapid, -40.0, 40.0);
    expectStep(f[5], Kind::Rapid, 5.0, 40.0);
}

TEST(PatternRepeat, AllowanceInZMovesThePassesInsteadOfOffsettingThem) {
    // L0.5 M0.2: the profile moved by (Z+0.2, r+0.5), then by the rest of the stock along X.
    PatternRepeat cycle = shoulder();
    cycle.allowanceZ = 0.2;
    const Vec2 call(5.0, 40.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error));
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_EQ(s.size(), 3u * 6u);
    expectStep(s[0], Kind::Rapid, 0.2, 14.0);
    expectStep(s[1], Kind::Feed, -19.8, 14.0);
    expectStep(s[2], Kind::Feed, -19.8, 24.0);
    // The profile's end is no wall: the pass runs on to it (Z-40), as without M.
    expectStep(s[3], Kind::Feed, -40.0, 24.0);
    expectStep(s[12], Kind::Rapid, 0.2, 10.5);
}

// Whether a point of the finished profile lies strictly inside the box [p - max, p - min]: the
// pass point p is then closer to the part than the allowances (|M| in Z, |L| in X) allow.
bool withinAllowances(const PatternRepeat& cycle, const Vec2& p, double m, double l) {
    Vec2 from = cycle.start;
    for (const ProfileElement& e : cycle.elements) {
        for (int j = 0; j <= 400; ++j) {
            const Vec2 q = from + (e.end - from) * (j / 400.0);
            if (std::fabs(p.x() - q.x()) < m - 1e-6 && std::fabs(p.y() - q.y()) < l - 1e-6)
                return true;
        }
        from = e.end;
    }
    return false;
}

void expectPass(const std::vector<LatheStep>& s, size_t first,
                const std::vector<std::pair<double, double>>& points) {
    ASSERT_GE(s.size(), first + points.size());
    expectStep(s[first], Kind::Rapid, points[0].first, points[0].second);
    for (size_t k = 1; k < points.size(); ++k)
        expectStep(s[first + k], Kind::Feed, points[k].first, points[k].second);
}

TEST(PatternRepeat, AllowanceInZKeepsBothWallsOfAGroove) {
    // r10 from the face to Z-10, a groove down to r7 between Z-10 and Z-15, r10 on to Z-30;
    // I2 C1 L0.5 M0.5 from Z5 r20: passes 1 and 0.5 out. The groove's near wall (Z-10) faces
    // away from the call point: its copy lies M beyond it at Z-10.5 (a copy moved bodily by +M
    // ran at Z-9.5, 0.5 into the collar); the far wall (Z-15) faces the call point: Z-14.5.
    // Diameters and the floor: L plus the rest of the stock, 10 + 0.5 + (d - 0.5), 7 + ...
    PatternRepeat cycle;
    cycle.start = Vec2(0.0, 10.0);
    cycle.elements = {lineTo(-10.0, 10.0), lineTo(-10.0, 7.0), lineTo(-15.0, 7.0),
                      lineTo(-15.0, 10.0), lineTo(-30.0, 10.0)};
    cycle.stock = 2.0;
    cycle.step = 1.0;
    cycle.allowanceX = 0.5;
    cycle.allowanceZ = 0.5;
    const Vec2 call(5.0, 20.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error)) << error.messageTemplate;
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_EQ(s.size(), 2u * 8u);
    expectPass(
        s, 0,
        {{0.5, 11.0}, {-10.5, 11.0}, {-10.5, 8.0}, {-14.5, 8.0}, {-14.5, 11.0}, {-30.0, 11.0}});
    expectStep(s[6], Kind::Rapid, -30.0, 20.0);
    expectStep(s[7], Kind::Rapid, 5.0, 20.0);
    expectPass(
        s, 8,
        {{0.5, 10.5}, {-10.5, 10.5}, {-10.5, 7.5}, {-14.5, 7.5}, {-14.5, 10.5}, {-30.0, 10.5}});
}

TEST(PatternRepeat, AllowanceInZFollowsAnUndercutWithoutCrossingIt) {
    // A dovetail: r10 to Z-10, down the collar's face to r6, then back towards the face under
    // the collar to (Z-6, r4), r4 to Z-20, a shoulder up to r10, r10 to Z-30. L0.5 M0.5, I2 C1.
    // Pass 0.5 (the box +-0.5 both ways): the collar's underside moved by (-0.5, -0.5) until it
    // meets the floor's copy r4.5 at Z-8.5 (x = 5.5 - (z + 10.5) / 2 = 4.5); the shoulder faces
    // the call point: Z-19.5. Pass 1 (the box reaches 0.5 + (1 - 0.5) up): the floor's copy r5
    // meets the underside's copy at Z-9.5 (x = 5.5 - (z + 10.5) / 2 = 5).
    PatternRepeat cycle;
    cycle.start = Vec2(0.0, 10.0);
    cycle.elements = {lineTo(-10.0, 10.0), lineTo(-10.0, 6.0),  lineTo(-6.0, 4.0),
                      lineTo(-20.0, 4.0),  lineTo(-20.0, 10.0), lineTo(-30.0, 10.0)};
    cycle.stock = 2.0;
    cycle.step = 1.0;
    cycle.allowanceX = 0.5;
    cycle.allowanceZ = 0.5;
    const Vec2 call(5.0, 20.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error)) << error.messageTemplate;
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_EQ(s.size(), 9u + 9u);
    expectPass(s, 0,
               {{0.5, 11.0},
                {-10.5, 11.0},
                {-10.5, 5.5},
                {-9.5, 5.0},
                {-19.5, 5.0},
                {-19.5, 11.0},
                {-30.0, 11.0}});
    expectPass(s, 9,
               {{0.5, 10.5},
                {-10.5, 10.5},
                {-10.5, 5.5},
                {-8.5, 4.5},
                {-19.5, 4.5},
                {-19.5, 10.5},
                {-30.0, 10.5}});
    for (size_t k = 1; k < s.size(); ++k) {
        if (s[k].kind != Kind::Feed) continue;
        for (int j = 0; j <= 20; ++j) {
            const Vec2 p = s[k - 1].to + (s[k].to - s[k - 1].to) * (j / 20.0);
            EXPECT_FALSE(withinAllowances(cycle, p, 0.5, 0.5)) << "step " << k;
        }
    }
}

TEST(PatternRepeat, AllowanceInZNeverComesCloserThanTheAllowancesOverRandomProfiles) {
    // Grooves, valleys and shoulders along -Z with L0.4 M0.7: no point of any pass lies closer
    // to the profile than 0.7 along Z and 0.4 along X at once.
    std::mt19937 random(1717);
    std::uniform_real_distribution<double> length(0.5, 8.0);
    std::uniform_real_distribution<double> rise(-6.0, 6.0);
    for (int trial = 0; trial < 100; ++trial) {
        PatternRepeat cycle;
        cycle.start = Vec2(0.0, 10.0);
        Vec2 at = cycle.start;
        for (int i = 0; i < 4; ++i) {
            // A step along Z, then a wall straight up or down: grooves of every width.
            at = Vec2(at.x() - length(random), at.y());
            cycle.elements.push_back(lineTo(at.x(), at.y()));
            at = Vec2(at.x(), std::max(2.0, at.y() + rise(random)));
            cycle.elements.push_back(lineTo(at.x(), at.y()));
        }
        at = Vec2(at.x() - length(random), at.y());
        cycle.elements.push_back(lineTo(at.x(), at.y()));
        cycle.stock = 4.0;
        cycle.step = 1.5;
        cycle.allowanceX = 0.4;
        cycle.allowanceZ = 0.7;
        const Vec2 call(10.0, 60.0);
        LathePath path(call);
        LatheError error;
        ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error))
            << "trial " << trial << ": " << error.messageTemplate;
        Vec2 from = call;
        for (const LatheStep& step : path.steps()) {
            if (step.kind == Kind::Feed) {
                for (int j = 0; j <= 8; ++j) {
                    const Vec2 p = from + (step.to - from) * (j / 8.0);
                    ASSERT_FALSE(withinAllowances(cycle, p, 0.7, 0.4)) << "trial " << trial;
                }
            }
            from = step.to;
        }
    }
}

TEST(PatternRepeat, PassesStopAtTheProfilesEndAlongZ) {
    // A convex round R10 about (Z-20, r10) ends the profile at Z-30; the pass 2 out is an arc of
    // R12 that would run on beyond Z-30 and is cut there, at r = 10 + sqrt(12^2 - 10^2).
    PatternRepeat cycle;
    cycle.start = Vec2(0.0, 20.0);
    cycle.elements = {lineTo(-20.0, 20.0), {Vec2(-30.0, 10.0), Vec2(-20.0, 10.0), true}};
    cycle.stock = 4.0;  // passes 2 and 0 out
    cycle.step = 2.0;
    const Vec2 call(5.0, 40.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error)) << error.messageTemplate;
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_GE(s.size(), 3u);
    expectStep(s[1], Kind::Feed, -20.0, 22.0);
    expectStep(s[2], Kind::FeedArc, -30.0, 10.0 + std::sqrt(44.0));
}

TEST(PatternRepeat, FacingPassesStepAlongZ) {
    // A1: a face from r30 down to r15 at Z0, a step back to Z-5, a face down to r5; called from
    // Z10 r40 with I4 C2: passes 2 and 0 out along +Z. At 2: Z2 down to r15, the part's outer
    // corner (Z0, r15) rounded clockwise with R2, r13 back to Z-3 (the inner corner cut), Z-3
    // down to r5; out along Z to Z10 first, then up to r40.
    PatternRepeat cycle;
    cycle.start = Vec2(0.0, 30.0);
    cycle.elements = {lineTo(0.0, 15.0), lineTo(-5.0, 15.0), lineTo(-5.0, 5.0)};
    cycle.stockAlongZ = true;
    cycle.stock = 4.0;
    cycle.step = 2.0;
    const Vec2 call(10.0, 40.0);
    LathePath path(call);
    LatheError error;
    ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error)) << error.messageTemplate;
    const std::vector<LatheStep>& s = path.steps();
    ASSERT_EQ(s.size(), 7u + 6u);  // the last pass, on the profile, has no rounded corner
    expectStep(s[0], Kind::Rapid, 2.0, 30.0);
    expectStep(s[1], Kind::Feed, 2.0, 15.0);
    expectStep(s[2], Kind::FeedArc, 0.0, 13.0);
    EXPECT_FALSE(s[2].ccw);
    expectStep(s[3], Kind::Feed, -3.0, 13.0);
    expectStep(s[4], Kind::Feed, -3.0, 5.0);
    expectStep(s[5], Kind::Rapid, 10.0, 5.0);
    expectStep(s[6], Kind::Rapid, 10.0, 40.0);
    expectStep(s[7], Kind::Rapid, 0.0, 30.0);
}

TEST(PatternRepeat, CallPointWithinTheStockIsRefused) {
    const Vec2 call(2.0, 14.0);  // 4.5 from the profile's start, the stock is 6
    LathePath path(call);
    LatheError error;
    EXPECT_FALSE(expandPatternRepeat(shoulder(), call, path, error));
    EXPECT_EQ(error.code, "cycle-position");
    EXPECT_EQ(error.letter, 'X');
}

// The shortest distance from p to the finished profile.
double distanceToProfile(const PatternRepeat& cycle, const Vec2& p) {
    double nearest = HUGE_VAL;
    Vec2 from = cycle.start;
    for (const ProfileElement& e : cycle.elements) {
        nearest = std::min(nearest, PlanarSegment::line(from, e.end).distanceTo(p));
        from = e.end;
    }
    return nearest;
}

TEST(PatternRepeat, EveryCutLiesAtItsPassDistanceOverRandomProfiles) {
    // Profiles of shoulders, tapers, valleys and grooves along -Z; each feed move of pass k,
    // sampled, must lie exactly I - k C (the last one L) from the profile: never closer (a gouge),
    // and no farther (a copy that is not an offset).
    std::mt19937 random(1416);
    std::uniform_real_distribution<double> length(1.0, 12.0);
    std::uniform_real_distribution<double> rise(-9.0, 8.0);
    for (int trial = 0; trial < 300; ++trial) {
        PatternRepeat cycle;
        cycle.start = Vec2(0.0, 10.0);
        Vec2 at = cycle.start;
        for (int i = 0; i < 6; ++i) {
            at = Vec2(at.x() - length(random), std::max(2.0, at.y() + rise(random)));
            cycle.elements.push_back(lineTo(at.x(), at.y()));
        }
        cycle.stock = 5.0;
        cycle.step = 1.5;
        cycle.allowanceX = 0.3;
        const Vec2 call(10.0, 80.0);
        LathePath path(call);
        LatheError error;
        ASSERT_TRUE(expandPatternRepeat(cycle, call, path, error))
            << "trial " << trial << ": " << error.messageTemplate;
        const double depths[] = {3.5, 2.0, 0.5, 0.3};
        int pass = -1;
        Vec2 from = call;
        for (const LatheStep& step : path.steps()) {
            if (step.kind == Kind::Rapid) {
                if (from == call) ++pass;
                from = step.to;
                continue;
            }
            ASSERT_LT(pass, 4);
            for (int j = 0; j <= 8; ++j) {
                Vec2 p = from + (step.to - from) * (j / 8.0);
                if (step.kind == Kind::FeedArc) {
                    const double r = (from - step.centre).norm();
                    p = step.centre + r * (p - step.centre).normalized();
                }
                EXPECT_NEAR(distanceToProfile(cycle, p), depths[pass], 1e-6)
                    << "trial " << trial << " pass " << pass;
            }
            from = step.to;
        }
        EXPECT_EQ(pass, 3) << "trial " << trial;
    }
}

}  // namespace
}  // namespace kerf::cycles::lathe
