// FAGOR lathe cycles as pure expansions: properties over many random sections and threads,
// checked against independent geometry (the finished section, the helix of the thread).
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/cycles/lathe/grooving.h"
#include "core/cycles/lathe/section_turning.h"
#include "core/cycles/lathe/threading.h"

namespace kerf::cycles::lathe {
namespace {

// Depth of p below the finished taper A-B of an external turning (> 0: inside the part).
double insidePart(const Vec2& p, const Vec2& a, const Vec2& b) {
    if (p.x() > a.x() || p.x() < b.x()) return -1.0;  // outside the section's Z range
    const double t = (p.x() - a.x()) / (b.x() - a.x());
    return a.y() + t * (b.y() - a.y()) - p.y();
}

// The step coordinates of a groove's plunges (Z for G88, X for G89) with a blade 3 wide, C as
// given, for the location code of the active offset.
std::vector<double> plunges(bool alongZ, Vec2 start, Vec2 end, double maxStep, int code) {
    Groove g;
    g.alongZ = alongZ;
    g.start = start;
    g.end = end;
    g.maxStep = maxStep;
    g.safety = 1.0;
    g.toolWidth = 3.0;
    g.locationCode = code;
    const Vec2 call = alongZ ? Vec2(start.x() + 5.0, start.y()) : Vec2(start.x(), start.y() + 5.0);
    LathePath path(call);
    LatheError error;
    EXPECT_TRUE(expandGroove(g, call, path, error)) << error.messageTemplate;
    std::vector<double> at;
    for (const LatheStep& step : path.steps()) {
        if (step.kind == LatheStep::Kind::Feed) at.push_back(alongZ ? step.to.y() : step.to.x());
    }
    return at;
}

TEST(LatheCycles, GroovePlungesPutTheBladeFlushWithBothWallsByItsLocationCode) {
    // G88 from Z-10 to R-16 (6 wide, blade 3, C3: two plunges). F5 is the blade's +Z corner: it
    // covers z-3..z, so Z-10 and Z-13; F3 its -Z corner (z..z+3): Z-13 and Z-16; F4 its middle:
    // Z-11.5 and Z-14.5; F0 names no edge: the width runs towards R, as F5 here.
    using V = std::vector<double>;
    const Vec2 s(-10.0, 25.0);
    const Vec2 e(-16.0, 21.0);
    EXPECT_EQ(plunges(false, s, e, 3.0, 5), (V{-10.0, -13.0}));
    EXPECT_EQ(plunges(false, s, e, 3.0, 3), (V{-13.0, -16.0}));
    EXPECT_EQ(plunges(false, s, e, 3.0, 4), (V{-11.5, -14.5}));
    EXPECT_EQ(plunges(false, s, e, 3.0, 0), (V{-10.0, -13.0}));
    // The same groove programmed from Z-16 to R-10: F3 at Z-16 and Z-13, F5 at Z-13 and Z-10.
    EXPECT_EQ(plunges(false, Vec2(-16.0, 25.0), Vec2(-10.0, 21.0), 3.0, 3), (V{-16.0, -13.0}));
    EXPECT_EQ(plunges(false, Vec2(-16.0, 25.0), Vec2(-10.0, 21.0), 3.0, 5), (V{-13.0, -10.0}));
    // G89 from r10 to r16 (C2: three plunges 1.5 apart). F2, a face blade, is its inner edge:
    // r10, 11.5, 13; F7 (tip towards +X) its outer edge: r13, 14.5, 16.
    EXPECT_EQ(plunges(true, Vec2(0.0, 10.0), Vec2(-3.0, 16.0), 2.0, 2), (V{10.0, 11.5, 13.0}));
    EXPECT_EQ(plunges(true, Vec2(0.0, 10.0), Vec2(-3.0, 16.0), 2.0, 7), (V{13.0, 14.5, 16.0}));
}

TEST(LatheCycles, TurningNeverCutsIntoTheSectionAndStepsAtMostC) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 500; ++trial) {
        TurningSection s;
        const Vec2 a(0.0, 5.0 + 20.0 * u(random));
        const Vec2 b(-5.0 - 40.0 * u(random), a.y() + 15.0 * u(random));
        s.start = a;
        s.elements.push_back({b, std::nullopt, false});
        s.maxStep = 0.2 + 3.0 * u(random);
        s.allowanceX = u(random) < 0.5 ? 0.0 : u(random);
        s.allowanceZ = u(random) < 0.5 ? 0.0 : u(random);
        const double pick = u(random);
        if (pick < 0.3) s.retract = 0.0;
        if (pick > 0.6) s.retract = 2.0 * u(random);
        s.finalRoughingFeed = u(random) < 0.5 ? 0.2 : 0.0;
        s.finishingFeed = u(random) < 0.5 ? 0.1 : 0.0;
        const Vec2 call(1.0 + s.allowanceZ, b.y() + s.allowanceX + 10.0 * u(random));
        LathePath path(call);
        LatheError error;
        ASSERT_TRUE(expandTurningSection(s, call, path, error)) << error.messageTemplate;
        Vec2 at = call;
        int cuts = 0;
        double lastLevel = call.y();
        for (const LatheStep& step : path.steps()) {
            // Sample the move: no point of it lies inside the finished section.
            for (int k = 0; k <= 20; ++k) {
                const Vec2 p = at + (step.to - at) * (k / 20.0);
                ASSERT_LE(insidePart(p, a, b), 1e-9) << "trial " << trial;
            }
            const bool roughing = step.kind == LatheStep::Kind::Feed && step.feed == 0.0 &&
                                  std::fabs(step.to.y() - at.y()) < 1e-12 &&
                                  std::fabs(at.x() - call.x()) < 1e-12;
            if (roughing) {
                ++cuts;
                EXPECT_LE(lastLevel - step.to.y(), s.maxStep + 1e-9);
                lastLevel = step.to.y();
            }
            at = step.to;
        }
        // ceil(depth / C) passes down to the section plus its allowance.
        const double depth = call.y() - (a.y() + s.allowanceX);
        EXPECT_EQ(cuts, static_cast<int>(std::ceil(depth / s.maxStep - 1e-9))) << trial;
        EXPECT_NEAR(lastLevel, a.y() + s.allowanceX, 1e-9);
        EXPECT_EQ((at - call).norm(), 0.0);  // ends at the call point
    }
}

// The radius of a profile of lines at z (z between its start and its end, decreasing).
double profileAt(const TurningSection& s, double z) {
    Vec2 from = s.start;
    for (const ProfileElement& e : s.elements) {
        if (z >= e.end.x() - 1e-12) {
            const double t = (from.x() - z) / (from.x() - e.end.x());
            return from.y() + t * (e.end.y() - from.y());
        }
        from = e.end;
    }
    return from.y();
}

TEST(LatheCycles, StockRemovalWithChannelsNeverCutsIntoTheProfile) {
    // G68 over random profiles that dip back into the material (channels within channels): no
    // point of any move, rapid or feed, lies inside the finished profile, and the roughing
    // reaches every channel's floor (some move touches the profile's lowest point).
    std::mt19937 random(68);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        TurningSection s;
        s.channels = true;
        s.start = Vec2(0.0, 10.0 + 10.0 * u(random));
        Vec2 at = s.start;
        double lowest = at.y();
        for (int i = 0; i < 8; ++i) {
            at = Vec2(at.x() - 1.0 - 6.0 * u(random), 2.0 + 25.0 * u(random));
            s.elements.push_back({at, std::nullopt, false});
            lowest = std::min(lowest, at.y());
        }
        s.maxStep = 0.5 + 3.0 * u(random);
        const double pick = u(random);
        if (pick < 0.3) s.retract = 0.0;
        if (pick > 0.6) s.retract = 2.0 * u(random);
        s.finishingFeed = u(random) < 0.5 ? 0.1 : 0.0;
        const Vec2 call(2.0, 30.0 + 5.0 * u(random));
        LathePath path(call);
        LatheError error;
        ASSERT_TRUE(expandTurningSection(s, call, path, error)) << error.messageTemplate;
        Vec2 from = call;
        bool floorReached = false;
        for (const LatheStep& step : path.steps()) {
            for (int k = 0; k <= 40; ++k) {
                const Vec2 p = from + (step.to - from) * (k / 40.0);
                if (p.x() > s.start.x() || p.x() < at.x()) continue;  // beyond A or B
                ASSERT_GE(p.y() - profileAt(s, p.x()), -1e-7)
                    << "trial " << trial << " at Z" << p.x() << " r" << p.y();
            }
            floorReached = floorReached || std::fabs(step.to.y() - lowest) < 1e-9;
            from = step.to;
        }
        EXPECT_TRUE(floorReached) << "trial " << trial;
    }
}

TEST(LatheCycles, EveryThreadPassStartsOnTheSameHelix) {
    std::mt19937 random(86);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        Thread t;
        t.start = {5.0, 20.0};
        t.end = {-30.0, 20.0 + (u(random) < 0.5 ? 0.0 : 5.0 * u(random))};
        t.depth = 0.5 + 2.0 * u(random);
        t.infeed = (u(random) < 0.5 ? 1.0 : -1.0) * (0.1 + 0.3 * u(random));
        t.finishing = 0.2 * (u(random) - 0.5);
        t.pitch = -(0.5 + 3.0 * u(random));  // along Z
        t.infeedAngleDeg = 60.0 * (u(random) - 0.3);
        t.spindleAngleDeg = 360.0 * u(random);
        t.starts = 1 + static_cast<int>(3.0 * u(random));
        t.safety = 1.0;
        LathePath path(Vec2(10.0, 30.0));
        LatheError error;
        ASSERT_TRUE(expandThread(t, Vec2(10.0, 30.0), path, error)) << error.messageTemplate;
        Vec2 at(10.0, 30.0);
        int threads = 0;
        for (const LatheStep& step : path.steps()) {
            if (step.kind == LatheStep::Kind::Thread) {
                ++threads;
                // The helix of start j passes Z = start at angle W + 360 j / V: a cut starting
                // at Z = z begins at W + 360 j / V + 360 (start - z) / P.
                const double turns = (t.start.x() - at.x()) / -t.pitch;
                double phase = step.angleDeg - t.spindleAngleDeg - 360.0 * turns;
                phase = std::fmod(std::fmod(phase, 360.0) + 360.0, 360.0);
                const double spacing = 360.0 / t.starts;
                const double offStart = std::fmod(phase + 1e-6, spacing) - 1e-6;
                EXPECT_NEAR(offStart, 0.0, 1e-6) << "trial " << trial;
                EXPECT_NEAR(step.lead * std::fabs(step.to.x() - at.x()) / (step.to - at).norm(),
                            -t.pitch, 1e-9);
            }
            at = step.to;
        }
        EXPECT_EQ(threads % t.starts, 0);
    }
}

}  // namespace
}  // namespace kerf::cycles::lathe
