// SL cycles 21-24 called directly with hand-made subcontours: the superimposed area, the depths,
// the clearing rings and the errors. Values derived by hand in the comments.
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/cycle_registry.h"

namespace kerf::cycles {
namespace {

constexpr double kPi = std::numbers::pi;

struct Move {
    enum Kind { Rapid, Line, Arc, SpatialArc } kind;
    Vec3 target;
    Vec2 centre;
    double sweep;
    Feed feed;
    Vec3 from = Vec3::Zero();     // spatial arcs
    Vec3 centre3 = Vec3::Zero();  // spatial arcs
};

struct Recorder final : CycleEmitter {
    std::vector<Move> moves;
    void rapid(const Vec3& t) override {
        moves.push_back({Move::Rapid, t, Vec2::Zero(), 0.0, Feed::rapid()});
    }
    void line(const Vec3& t, const Feed& f) override {
        moves.push_back({Move::Line, t, Vec2::Zero(), 0.0, f});
    }
    void arc(const Vec3& t, const Vec2& c, double s, const Feed& f) override {
        moves.push_back({Move::Arc, t, c, s, f});
    }
    void spatialArc(const Vec3& from, const Vec3& t, const Vec3& c, const Feed& f) override {
        moves.push_back({Move::SpatialArc, t, Vec2::Zero(), 0.0, f, from, c});
    }
    void threadMove(const Vec3&, double, double) override {}
    void dwell(double) override {}
    void spindle(canon::SpindleDirection, double) override {}
    void orientSpindle(double) override {}
    void miscFunction(int) override {}

    // Arcs at height w about the origin with radius r.
    size_t arcsAbout(const Vec2& centre, double r, double w) const {
        size_t n = 0;
        for (const Move& m : moves) {
            const Vec2 end(m.target.x(), m.target.y());
            if (m.kind == Move::Arc && std::fabs(m.target.z() - w) < 1e-9 &&
                (m.centre - centre).norm() < 1e-9 && std::fabs((end - centre).norm() - r) < 1e-9) {
                ++n;
            }
        }
        return n;
    }
    // Total angle turned on arcs at height w about `centre` with radius r.
    double turnAbout(const Vec2& centre, double r, double w) const {
        double sum = 0.0;
        for (const Move& m : moves) {
            const Vec2 end(m.target.x(), m.target.y());
            if (m.kind == Move::Arc && std::fabs(m.target.z() - w) < 1e-9 &&
                (m.centre - centre).norm() < 1e-9 && std::fabs((end - centre).norm() - r) < 1e-9) {
                sum += std::fabs(m.sweep);
            }
        }
        return sum;
    }
};

ClosedContour rectangle(double u0, double v0, double u1, double v1) {
    const Vec2 p[] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    ClosedContour c;
    for (size_t i = 0; i < 4; ++i)
        c.segments.push_back(PlanarSegment::line(p[i], p[(i + 1) % 4]));
    return c;
}

CycleValues contourData(double depth, double side, double floor) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {{1, depth}, {2, 1.0}, {3, side},
                                                  {4, floor}, {5, 0.0}, {6, 2.0},
                                                  {7, 50.0},  {8, 0.0}, {9, 1.0}};
    for (auto [q, value] : values)
        v.set(q, value);
    return v;
}

// The example: a 60 x 40 pocket about the origin, an island of 20 mm diameter in its
// middle, tool R5.
CycleContext pocketWithIsland(const CycleValues& data, double islandRadius = 10.0) {
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.contours.push_back({rectangle(-30, -20, 30, 20), false, 1});
    ctx.contours.push_back({circleContour(islandRadius), true, 2});
    ctx.contourData = &data;
    return ctx;
}

std::optional<CycleError> run(int cycle, const CycleValues& v, const CycleContext& ctx,
                              Recorder& out) {
    CyclePath path(out, ctx.start);
    return findCycle(cycle)->expand(v, ctx, path);
}

CycleValues roughOut(double plungingDepth) {
    CycleValues v;
    v.set(10, plungingDepth);
    v.set(11, 100.0);
    v.set(12, 350.0);
    v.set(18, 0.0);
    v.set(19, 0.0);
    v.set(208, 0.0);
    return v;
}

// Allowance 0.5, overlap 1: tool-centre rings at 5.5 and 10.5 from the walls. Ring 1: the
// rectangle |u| <= 24.5, |v| <= 14.5 less the circle 10 + 5 + 0.5 = 15.5, which reaches beyond
// v = 14.5: two regions, each closed by an arc of radius 15.5. Ring 2: |u| <= 19.5, |v| <= 9.5
// less the circle 20.5, which also crosses u = +-19.5 (at v = +-sqrt(20.5^2 - 19.5^2)): four
// corner regions, each with an arc of radius 20.5. At
// 15.5 from the walls (|v| <= 4.5, circle 25.5) nothing is left. Depth 10 in infeeds of 5.
TEST(SlCycles, RoughOutClearsAroundTheIslandAtEachInfeed) {
    const CycleValues data = contourData(-10.0, 0.5, 0.0);
    Recorder out;
    ASSERT_FALSE(run(22, roughOut(5.0), pocketWithIsland(data), out));
    // The arcs (a pass may start inside one and end on its rest): 15.5 from v = 14.5 to -14.5
    // on each side, 20.5 between v = 9.5 and v = sqrt(40) in each corner.
    const double ring1 = 4.0 * std::atan2(14.5, std::sqrt(30.0));
    const double ring2 = 4.0 * (std::asin(9.5 / 20.5) - std::asin(std::sqrt(40.0) / 20.5));
    for (double w : {-5.0, -10.0}) {
        EXPECT_NEAR(out.turnAbout({0.0, 0.0}, 15.5, w), ring1, 1e-9) << w;
        EXPECT_NEAR(out.turnAbout({0.0, 0.0}, 20.5, w), ring2, 1e-9) << w;
        EXPECT_GE(out.arcsAbout({0.0, 0.0}, 20.5, w), 4u) << w;
    }
    double lowest = 1e9;
    for (const Move& m : out.moves) {
        lowest = std::min(lowest, m.target.z());
        if (m.target.z() >= 0.0) continue;
        // Never nearer than R + allowance to a wall or to the island.
        EXPECT_LE(std::fabs(m.target.x()), 24.5 + 1e-9);
        EXPECT_LE(std::fabs(m.target.y()), 14.5 + 1e-9);
        EXPECT_GE(Vec2(m.target.x(), m.target.y()).norm(), 15.5 - 1e-9);
    }
    EXPECT_NEAR(lowest, -10.0, 1e-12);
    // Every plunge is at Q11 and every move in the plane at Q12; the end at Q7 at Q12 (Q208 0).
    for (size_t i = 1; i < out.moves.size(); ++i) {
        const Move& m = out.moves[i];
        if (m.kind == Move::Rapid) continue;
        const Vec3 from = out.moves[i - 1].target;
        const bool down = m.target.z() < from.z() - 1e-9;
        const bool up = m.target.z() > from.z() + 1e-9;
        EXPECT_DOUBLE_EQ(m.feed.value, down ? 100.0 : 350.0) << i;
        if (up) {
            EXPECT_NEAR(m.target.z(), 50.0, 1e-12);
        }
    }
    EXPECT_NEAR(out.moves.back().target.z(), 50.0, 1e-12);
}

// A smaller island (r 3): ring 1 has a hole of radius 3 + 5.5 = 8.5; ring 2 (|v| <= 9.5) is cut
// by the circle 13.5 into two regions whose arcs span 4 asin(9.5 / 13.5) together; ring 3
// (|v| <= 4.5, circle 18.5) is empty. Q9 = -1 runs them the other way.
TEST(SlCycles, UpCutRunsTheRingsTheOtherWay) {
    CycleValues data = contourData(-5.0, 0.5, 0.0);
    Recorder climb;
    ASSERT_FALSE(run(22, roughOut(5.0), pocketWithIsland(data, 3.0), climb));
    data.set(9, -1.0);
    Recorder upCut;
    ASSERT_FALSE(run(22, roughOut(5.0), pocketWithIsland(data, 3.0), upCut));
    auto sweepAbout = [](const Recorder& r, double radius) {
        double sum = 0.0;
        for (const Move& m : r.moves) {
            const Vec2 end(m.target.x(), m.target.y());
            if (m.kind == Move::Arc && m.centre.norm() < 1e-9 &&
                std::fabs(end.norm() - radius) < 1e-9) {
                sum += m.sweep;
            }
        }
        return sum;
    };
    // Climb: the holes clockwise (the area on the left), up-cut counter-clockwise.
    EXPECT_NEAR(sweepAbout(climb, 8.5), -2.0 * kPi, 1e-9);
    EXPECT_NEAR(sweepAbout(upCut, 8.5), 2.0 * kPi, 1e-9);
    EXPECT_NEAR(sweepAbout(climb, 13.5), -4.0 * std::asin(9.5 / 13.5), 1e-9);
    EXPECT_NEAR(sweepAbout(upCut, 13.5), 4.0 * std::asin(9.5 / 13.5), 1e-9);
}

// Cycle 21 drills where 22 plunges: depth 10 less the floor allowance 0.5 in infeeds of 5: down
// to -5 at Q11, out to the set-up clearance, back to 0.6 mm above -5, down to -9.5.
TEST(SlCycles, PilotDrillingPecksToTheDepthLessTheFloorAllowance) {
    const CycleValues data = contourData(-10.0, 0.5, 0.5);
    CycleValues v;
    v.set(10, 5.0);
    v.set(11, 250.0);
    v.set(13, 0.0);
    Recorder out;
    ASSERT_FALSE(run(21, v, pocketWithIsland(data, 3.0), out));
    std::vector<double> feeds;
    for (const Move& m : out.moves) {
        if (m.kind == Move::Line) feeds.push_back(m.target.z());
    }
    ASSERT_GE(feeds.size(), 2u);
    EXPECT_NEAR(feeds[0], -5.0, 1e-12);
    EXPECT_NEAR(feeds[1], -9.5, 1e-12);
    bool advancedStop = false;
    for (const Move& m : out.moves)
        advancedStop =
            advancedStop || (m.kind == Move::Rapid && std::fabs(m.target.z() + 4.4) < 1e-12);
    EXPECT_TRUE(advancedStop);
    EXPECT_NEAR(out.moves.back().target.z(), 50.0, 1e-12);
}

// Cycle 24 after roughing with R5 and Q3 0.5: the walls at R5 + Q14 0: the rectangle |u| <= 25,
// |v| <= 15 and the circle 8 + 5 = 13 about the island, each at depths 5 and 10.
TEST(SlCycles, SideFinishingFollowsEveryBoundaryAtEachInfeed) {
    const CycleValues data = contourData(-10.0, 0.5, 0.0);
    CycleContext ctx = pocketWithIsland(data, 8.0);
    ctx.roughingRadius = 5.0;
    CycleValues v;
    v.set(9, 1.0);
    v.set(10, 5.0);
    v.set(11, 100.0);
    v.set(12, 400.0);
    v.set(14, 0.0);
    Recorder out;
    ASSERT_FALSE(run(24, v, ctx, out));
    for (double w : {-5.0, -10.0})
        EXPECT_EQ(out.arcsAbout({0.0, 0.0}, 13.0, w), 1u) << w;
    size_t wallLines = 0;
    for (const Move& m : out.moves) {
        if (m.kind != Move::Line || m.target.z() > -5.0 + 1e-9) continue;
        if (std::fabs(std::fabs(m.target.x()) - 25.0) < 1e-9 ||
            std::fabs(std::fabs(m.target.y()) - 15.0) < 1e-9) {
            ++wallLines;
        }
    }
    EXPECT_GE(wallLines, 8u);  // four sides at two depths
    // Q14 + R must stay below Q3 + R(roughing): 0 + 5 < 0.5 + 5, but 0.6 + 5 is not.
    v.set(14, 0.6);
    Recorder refused;
    auto error = run(24, v, ctx, refused);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-tool");
}

TEST(SlCycles, ErrorsWithoutContourOrDataAndForATooLargeTool) {
    const CycleValues data = contourData(-10.0, 0.5, 0.0);
    Recorder out;
    CycleContext ctx = pocketWithIsland(data);
    ctx.contourData = nullptr;
    auto noData = run(22, roughOut(5.0), ctx, out);
    ASSERT_TRUE(noData);
    EXPECT_EQ(noData->code, "cycle-contour");
    ctx = pocketWithIsland(data);
    ctx.contours.clear();
    auto noContour = run(22, roughOut(5.0), ctx, out);
    ASSERT_TRUE(noContour);
    EXPECT_EQ(noContour->code, "cycle-contour");
    ctx = pocketWithIsland(data);
    ctx.tool.radius = 20.0;  // 40 mm wide pocket: no room for R20 + 0.5
    auto tooLarge = run(22, roughOut(5.0), ctx, out);
    ASSERT_TRUE(tooLarge);
    EXPECT_EQ(tooLarge->code, "cycle-tool");
}

// Q8 rounds the inside corners of the tool-centre paths: a 60 x 40 pocket, tool R5, no
// allowance: the outermost path is the rectangle |u| <= 25, |v| <= 15, its corners arcs of
// radius 3 about (+-22, +-12) with Q8 = 3 (a quarter turn each), sharp without Q8.
TEST(SlCycles, RoundingRadiusRoundsTheInsideCornersOfThePaths) {
    CycleValues data = contourData(-5.0, 0.0, 0.0);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.contours.push_back({rectangle(-30, -20, 30, 20), false, 1});
    ctx.contourData = &data;
    Recorder sharp;
    ASSERT_FALSE(run(22, roughOut(5.0), ctx, sharp));
    data.set(8, 3.0);
    Recorder rounded;
    ASSERT_FALSE(run(22, roughOut(5.0), ctx, rounded));
    for (const Vec2& corner : {Vec2(22, 12), Vec2(-22, 12), Vec2(-22, -12), Vec2(22, -12)}) {
        EXPECT_NEAR(rounded.turnAbout(corner, 3.0, -5.0), kPi / 2.0, 1e-9) << corner.transpose();
        EXPECT_EQ(sharp.arcsAbout(corner, 3.0, -5.0), 0u);
    }
    for (const Move& m : rounded.moves) {
        // No point beyond the rounded corner: (|u| - 22)^2 + (|v| - 12)^2 <= 3^2 in the corners.
        const double du = std::fabs(m.target.x()) - 22.0, dv = std::fabs(m.target.y()) - 12.0;
        if (du > 0.0 && dv > 0.0) {
            EXPECT_LE(std::hypot(du, dv), 3.0 + 1e-9);
        }
    }
}

// Spec §6.2 with the circles of the seed: pocket A (r 25 about X35 Y50) and B (about X65).
TEST(SlCycles, SuperimposedPocketsUnionIntersectionDifference) {
    const CycleValues data = contourData(-10.0, 0.0, 0.0);
    auto circleAt = [](double u) { return circleContour(25.0).placed({u, 50.0}, 0.0); };
    const double lens = 2.0 * 625.0 * std::acos(0.6) - 15.0 * 40.0;
    CycleContext ctx;
    ctx.contourData = &data;
    // A starts at X10 (outside B): the sum.
    ctx.contours = {{startingNearest(circleAt(35.0), {10.0, 50.0}), false, 1},
                    {circleAt(65.0), false, 2}};
    contour::ContourData d;
    d.depth = 10.0;
    contour::ContourArea area;
    ASSERT_FALSE(contour::combineContours(22, ctx, d, area));
    EXPECT_NEAR(area.area.area(), 2.0 * kPi * 625.0 - lens, 1e-6);
    // A starts at X60 (inside B): the intersection.
    ctx.contours[0].contour = startingNearest(circleAt(35.0), {60.0, 50.0});
    ASSERT_FALSE(contour::combineContours(22, ctx, d, area));
    EXPECT_NEAR(area.area.area(), lens, 1e-6);
    // B an island: the difference.
    ctx.contours[1].island = true;
    ASSERT_FALSE(contour::combineContours(22, ctx, d, area));
    EXPECT_NEAR(area.area.area(), kPi * 625.0 - lens, 1e-6);
}

// Q401 50 %: a 60 x 40 pocket, tool R5, no allowance, overlap 1: tool-centre rings |u| <= 25,
// |v| <= 15 (level 0), 20 x 10 (level 1) and 15 x 5 (level 2, the innermost: at 20 x 0 nothing
// is left). Only the innermost ring, which nothing was cleared inside, cuts with the full
// circumference: its moves at 350 x 50 % = 175, the others (and the stepovers) at 350.
TEST(SlCycles, FeedRateFactorSlowsTheFullWidthRingOnly) {
    const CycleValues data = contourData(-5.0, 0.0, 0.0);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.contours.push_back({rectangle(-30, -20, 30, 20), false, 1});
    ctx.contourData = &data;
    CycleValues v = roughOut(5.0);
    v.set(401, 50.0);
    Recorder out;
    ASSERT_FALSE(run(22, v, ctx, out));
    auto onRing = [](const Vec3& p, double hu, double hv) {
        const double u = std::fabs(p.x()), w = std::fabs(p.y());
        return (std::fabs(u - hu) < 1e-9 && w <= hv + 1e-9) ||
               (std::fabs(w - hv) < 1e-9 && u <= hu + 1e-9);
    };
    size_t slow = 0, fast = 0;
    for (size_t i = 1; i < out.moves.size(); ++i) {
        const Move& m = out.moves[i];
        if (m.kind != Move::Line || std::fabs(m.target.z() + 5.0) > 1e-9) continue;
        if (std::fabs(out.moves[i - 1].target.z() + 5.0) > 1e-9) continue;  // the plunge
        if (onRing(m.target, 15.0, 5.0)) {
            EXPECT_DOUBLE_EQ(m.feed.value, 175.0) << i;
            ++slow;
        } else {
            EXPECT_TRUE(onRing(m.target, 20.0, 10.0) || onRing(m.target, 25.0, 15.0)) << i;
            EXPECT_DOUBLE_EQ(m.feed.value, 350.0) << i;
            ++fast;
        }
    }
    EXPECT_GE(slow, 4u);  // the four sides of the innermost ring
    EXPECT_GE(fast, 8u);  // the sides of the other two, and the stepovers
}

// Q19 with a tool ANGLE of 10 degrees: the plunge is a helix of the tool radius 5 (room: the
// innermost ring 15 x 5 of the same 60 x 40 pocket starts 10 from every wall of the tool-centre
// region) at Q19, climbing (Q9 +1) counter-clockwise. Per turn it descends
// 2 pi 5 tan 10 deg = 5.53946; from the set-up clearance +2 to -5 (7 mm) that is one full turn
// and 0.26365 of one, then a straight move back to the helix's start on the ring.
TEST(SlCycles, PlungeOnAHelixAtTheToolsAngle) {
    const CycleValues data = contourData(-10.0, 0.0, 0.0);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.tool.plungeAngleDeg = 10.0;
    ctx.contours.push_back({rectangle(-30, -20, 30, 20), false, 1});
    ctx.contourData = &data;
    CycleValues v = roughOut(5.0);
    v.set(19, 150.0);
    Recorder out;
    ASSERT_FALSE(run(22, v, ctx, out));
    const double pitch = 2.0 * kPi * 5.0 * std::tan(10.0 * kPi / 180.0);
    for (const double top : {2.0, -3.0}) {  // the re-entry heights: surface, -5 (+ 2)
        size_t i = 0;
        while (i < out.moves.size() && !(out.moves[i].kind == Move::Rapid &&
                                         std::fabs(out.moves[i].target.z() - top) < 1e-9))
            ++i;
        ASSERT_LT(i + 3, out.moves.size()) << top;
        const Vec3 start = out.moves[i].target;
        const Move& turn = out.moves[i + 1];
        const Move& rest = out.moves[i + 2];
        const Move& back = out.moves[i + 3];
        ASSERT_EQ(turn.kind, Move::Arc);
        ASSERT_EQ(rest.kind, Move::Arc);
        EXPECT_NEAR(turn.sweep, 2.0 * kPi, 1e-9);
        EXPECT_NEAR(turn.target.z(), top - pitch, 1e-9);
        EXPECT_NEAR(rest.sweep, 2.0 * kPi * (7.0 - pitch) / pitch, 1e-9);
        EXPECT_NEAR(rest.target.z(), top - 7.0, 1e-9);
        EXPECT_NEAR((turn.centre - Vec2(start.x(), start.y())).norm(), 5.0, 1e-9);
        EXPECT_DOUBLE_EQ(turn.feed.value, 150.0);
        EXPECT_EQ(back.kind, Move::Line);
        EXPECT_NEAR((Vec2(back.target.x(), back.target.y()) - Vec2(start.x(), start.y())).norm(),
                    0.0, 1e-9);
        // The start lies on the innermost ring |u| <= 15, |v| <= 5.
        EXPECT_TRUE(std::fabs(std::fabs(start.x()) - 15.0) < 1e-9 ||
                    std::fabs(std::fabs(start.y()) - 5.0) < 1e-9);
    }
    // A pocket 12 x 60: the tool-centre strip |u| <= 1 has room for circles of radius 1 at most,
    // less than the smallest helix tried (5 / 4 = 1.25): an error, not a gouge.
    ctx.contours.clear();
    ctx.contours.push_back({rectangle(-6, -30, 6, 30), false, 1});
    Recorder narrow;
    const auto error = run(22, v, ctx, narrow);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-plunge");

    // A tool R 0.01 at ANGLE 0.1 deg in a 1 x 1 pocket: 2 pi 0.01 tan 0.1 deg = 0.00011 mm per
    // turn, so the 7 mm of the first plunge would take 63,800 turns: refused (at most 10,000),
    // not expanded into millions of moves.
    ctx.tool.radius = 0.01;
    ctx.tool.plungeAngleDeg = 0.1;
    ctx.contours.clear();
    ctx.contours.push_back({rectangle(-0.5, -0.5, 0.5, 0.5), false, 1});
    Recorder tiny;
    const auto tooMany = run(22, v, ctx, tiny);
    ASSERT_TRUE(tooMany);
    EXPECT_EQ(tooMany->code, "cycle-limit");
    EXPECT_TRUE(tiny.moves.empty());
}

// Where no helix fits (spec: "e.g. a slot"), the tool reciprocates over LCUTS / tan(ANGLE) along
// its path. The 12 x 60 pocket with R5: the tool-centre ring |u| <= 1, |v| <= 25 (perimeter
// 104) has no room for a helix of 1.25. LCUTS 2, ANGLE 10: strokes of 2 / tan 10 = 11.343,
// each descending at most 2. First plunge Z2 -> Z-5 (7): 4 strokes of 1.75, the last ending
// at the start; the second Z-3 -> Z-10 the same. All on the ring, never steeper than ANGLE.
TEST(SlCycles, PlungeReciprocatingWhereNoHelixFits) {
    const CycleValues data = contourData(-10.0, 0.0, 0.0);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.tool.plungeAngleDeg = 10.0;
    ctx.tool.cuttingLength = 2.0;
    ctx.contours.push_back({rectangle(-6, -30, 6, 30), false, 1});
    ctx.contourData = &data;
    CycleValues v = roughOut(5.0);
    v.set(19, 150.0);
    Recorder out;
    ASSERT_FALSE(run(22, v, ctx, out));
    const double tanA = std::tan(10.0 * kPi / 180.0);
    const double strokeLength = 2.0 / tanA;
    for (const auto& [top, bottom] : {std::pair{2.0, -5.0}, std::pair{-3.0, -10.0}}) {
        size_t i = 0;
        while (i < out.moves.size() && !(out.moves[i].kind == Move::Rapid &&
                                         std::fabs(out.moves[i].target.z() - top) < 1e-9))
            ++i;
        ASSERT_LT(i, out.moves.size()) << top;
        const Vec3 start = out.moves[i].target;
        Vec3 at = start;
        double travelled = 0.0;
        std::vector<double> strokeEnds;  // the heights where the tool is back at a stroke end
        for (++i; i < out.moves.size() && at.z() > bottom + 1e-9; ++i) {
            const Move& m = out.moves[i];
            ASSERT_EQ(m.kind, Move::Line) << "the ring's strokes here are lines";
            EXPECT_DOUBLE_EQ(m.feed.value, 150.0);
            const double planar = std::hypot(m.target.x() - at.x(), m.target.y() - at.y());
            ASSERT_GT(planar, 1e-9) << "no vertical plunge";
            EXPECT_LE((at.z() - m.target.z()) / planar, tanA + 1e-9);
            EXPECT_TRUE(std::fabs(std::fabs(m.target.x()) - 1.0) < 1e-9 ||
                        std::fabs(std::fabs(m.target.y()) - 25.0) < 1e-9);
            travelled += planar;
            at = m.target;
            if (std::fabs(std::fmod(travelled + 1e-6, strokeLength)) < 1e-5)
                strokeEnds.push_back(at.z());
        }
        EXPECT_NEAR(at.z(), bottom, 1e-9);
        EXPECT_NEAR(travelled, 4.0 * strokeLength, 1e-6);
        ASSERT_EQ(strokeEnds.size(), 4u);
        for (size_t k = 0; k < 4; ++k)
            EXPECT_NEAR(strokeEnds[k], top - 1.75 * static_cast<double>(k + 1), 1e-9);
        EXPECT_NEAR((Vec2(at.x(), at.y()) - Vec2(start.x(), start.y())).norm(), 0.0, 1e-9);
    }
    // Without LCUTS there is no reciprocating plunge either: the error stays.
    ctx.tool.cuttingLength = 0.0;
    Recorder none;
    const auto error = run(22, v, ctx, none);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-plunge");
}

// Q404 = 1: between separate rest areas the tool lifts to Q6 above the surface. A 20 x 12
// pocket after a coarse R5 (its centre reaches |u| <= 5, |v| <= 1): rest material in the four
// corners, on the walls beyond |v| = 1 and |u| = 5, so the corners of one end are 2 apart
// along the wall. For the fine R2 (room |u| <= 8, |v| <= 4) the rest grown by 2 keeps them
// apart ((-8, 0) is sqrt 5 > 2 from the rest's nearest point (-10, 1)): four areas, each
// plunged into from Q6 above the surface, one in each corner, the tool never below the
// surface between them. R2 is less than half of R5, where Q404 does not apply (spec: only for
// a fine tool of at least half the coarse one's radius): Q404 = 0 lifts the same way.
TEST(SlCycles, FineRoughingStrategyLiftsBetweenRestAreas) {
    for (double strategy : {1.0, 0.0}) {
        SCOPED_TRACE(strategy);
        const CycleValues data = contourData(-4.0, 0.0, 0.0);
        CycleContext ctx;
        ctx.start = {0.0, 0.0, 100.0};
        ctx.tool.radius = 2.0;
        ctx.contours.push_back({rectangle(-10, -6, 10, 6), false, 1});
        ctx.contourData = &data;
        ctx.toolByNumber = [](int) {
            ToolInfo coarse;
            coarse.radius = 5.0;
            return std::optional<ToolInfo>(coarse);
        };
        CycleValues v = roughOut(0.0);
        v.set(18, 7.0);
        v.set(404, strategy);
        Recorder out;
        ASSERT_FALSE(run(22, v, ctx, out));
        // Plunges: a feed move straight down to the depth right after a rapid to Z2.
        std::set<std::pair<bool, bool>> corners;
        size_t plunges = 0;
        for (size_t i = 1; i < out.moves.size(); ++i) {
            const Move& before = out.moves[i - 1];
            const Move& m = out.moves[i];
            if (before.kind != Move::Rapid || std::fabs(before.target.z() - 2.0) > 1e-9 ||
                m.kind == Move::Rapid) {
                continue;
            }
            ASSERT_EQ(m.kind, Move::Line);
            EXPECT_NEAR(m.target.z(), -4.0, 1e-9);
            EXPECT_NEAR(
                (Vec2(m.target.x(), m.target.y()) - Vec2(before.target.x(), before.target.y()))
                    .norm(),
                0.0, 1e-9);
            ++plunges;
            corners.insert({m.target.x() > 0.0, m.target.y() > 0.0});
        }
        EXPECT_EQ(plunges, 4u);
        EXPECT_EQ(corners.size(), 4u) << "one area in each corner";
        // Every cut stays in the fine tool's room and beside the coarse reach: |u| >= 5 - 1e-6.
        for (const Move& m : out.moves) {
            if (m.kind == Move::Rapid || m.target.z() > 0.0) continue;
            EXPECT_LE(std::fabs(m.target.x()), 8.0 + 1e-6);
            EXPECT_LE(std::fabs(m.target.y()), 4.0 + 1e-6);
            EXPECT_GE(std::fabs(m.target.x()), 5.0 - 1e-6);
        }
    }
}

// Q404 = 0: between the rest areas the tool stays at the depth and runs along the contour (the
// fine tool's tool-centre path |u| <= 8, |v| <= 4). The 20 x 12 pocket after a coarse R4 (half
// of it is the fine R2: Q404 applies): its centre reached |u| <= 6, |v| <= 2, leaving each
// corner of the pocket outside the arc of radius 4 about (+-6, +-2). The fine tool's part of
// the lower left one: the square [-8, -6] x [-4, -2] outside the circle of radius 2 about
// (-6, -2) (its points within 2 of the rest), the others mirrored. One ring per area (shrunk by
// the step 2 nothing is left), each starting where it is nearest the start of the one before:
// (-8, -4) (nearest the contour's start (-10, -6)), then (-8, 2) (6 away), then (6, 4) (14
// away), then (8, -2) (sqrt 40 away). The links run up the wall u = -8 from v = -4 to 2; from
// (-8, 2) up to (-8, 4) and along v = 4 to (6, 4); from (6, 4) to (8, 4) and down to (8, -2).
// One plunge only.
TEST(SlCycles, FineRoughingAlongTheContourBetweenRestAreas) {
    const CycleValues data = contourData(-4.0, 0.0, 0.0);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 2.0;
    ctx.contours.push_back({rectangle(-10, -6, 10, 6), false, 1});
    ctx.contourData = &data;
    ctx.toolByNumber = [](int) {
        ToolInfo coarse;
        coarse.radius = 4.0;
        return std::optional<ToolInfo>(coarse);
    };
    CycleValues v = roughOut(0.0);
    v.set(18, 7.0);
    v.set(404, 0.0);
    Recorder out;
    ASSERT_FALSE(run(22, v, ctx, out));
    size_t plunges = 0;
    std::vector<Vec2> wallPoints;  // moves at the depth ending on the walls' corners
    bool down = false;
    for (const Move& m : out.moves) {
        if (m.kind == Move::Rapid) {
            EXPECT_FALSE(down) << "no rapid at the depth";
            continue;
        }
        const bool atDepth = std::fabs(m.target.z() + 4.0) < 1e-9;
        if (atDepth && !down) ++plunges;
        down = atDepth;
        if (!atDepth) continue;
        EXPECT_LE(std::fabs(m.target.x()), 8.0 + 1e-6);
        EXPECT_LE(std::fabs(m.target.y()), 4.0 + 1e-6);
        if (m.kind == Move::Line) wallPoints.emplace_back(m.target.x(), m.target.y());
    }
    EXPECT_EQ(plunges, 1u);
    // The link ends and the room's corners it turns round, in this order.
    const Vec2 expected[] = {{-8, 2}, {-8, 4}, {6, 4}, {8, 4}, {8, -2}};
    size_t found = 0;
    for (const Vec2& p : wallPoints) {
        if (found < std::size(expected) && (p - expected[found]).norm() < 1e-6) ++found;
    }
    EXPECT_EQ(found, std::size(expected));
}

// A link along the contour never runs through a rest area whose passes are still to come (its
// material would be cut at the link). Room |u| <= 8, |v| <= 4; three areas, squares on the
// bottom wall: A [-8, -7] x [-4, -3], B [7, 8] x [-4, -3], C [-1, 1] x [-4, -3], passes in the
// order A, B, C, each ring from its lower left corner ((-8, -4), (7, -4), (-1, -4)). A to B:
// the shorter way is along v = -4 (15) through C, still to come, so the link goes round the
// other way (up to (-8, 4), along the top to (8, 4), down to (8, -4), back to (7, -4): 8 + 16 +
// 8 + 1 = 33). B to C: along v = -4 to (-1, -4) (8; C is its own area). With a fourth area D
// [-1, 1] x [3, 4] on the top wall after C, A to B is blocked both ways: the tool lifts.
TEST(SlCycles, LinkAlongTheContourAvoidsRestAreasStillToCome) {
    const Region room = regionOf(rectangle(-8, -4, 8, 4));
    const auto passesOf = [](const std::vector<ClosedContour>& rings) {
        std::vector<contour::ClearingPass> passes;
        for (const ClosedContour& ring : rings) {
            contour::ClearingPass p;
            p.path = ring;
            passes.push_back(p);
        }
        return passes;
    };
    const ClosedContour a = rectangle(-8, -4, -7, -3);
    const ClosedContour b = rectangle(7, -4, 8, -3);
    const ClosedContour c = rectangle(-1, -4, 1, -3);
    std::vector<contour::ClearingPass> passes = passesOf({a, b, c});
    Region rest;
    rest.boundaries = {a, b, c};
    contour::linkAlongContour(passes, room, rest);
    ASSERT_TRUE(passes[1].straightLink);
    std::vector<Vec2> ends;
    double length = 0.0;
    for (const PlanarSegment& s : passes[1].contourLink) {
        ends.push_back(s.end);
        length += s.length();
    }
    EXPECT_NEAR(length + (ends.back() - Vec2(7, -4)).norm(), 33.0, 1e-9);
    const Vec2 corners[] = {{-8, 4}, {8, 4}, {8, -4}};
    size_t found = 0;
    for (const Vec2& p : ends) {
        if (found < std::size(corners) && (p - corners[found]).norm() < 1e-9) ++found;
    }
    EXPECT_EQ(found, std::size(corners));
    ASSERT_TRUE(passes[2].straightLink);
    double toC = 0.0;
    for (const PlanarSegment& s : passes[2].contourLink) {
        EXPECT_NEAR(s.end.y(), -4.0, 1e-9);
        toC += s.length();
    }
    EXPECT_NEAR(toC, 8.0, 1e-9);

    const ClosedContour d = rectangle(-1, 3, 1, 4);
    passes = passesOf({a, b, c, d});
    rest.boundaries = {a, b, c, d};
    contour::linkAlongContour(passes, room, rest);
    EXPECT_FALSE(passes[1].straightLink);
    EXPECT_TRUE(passes[1].contourLink.empty());
    EXPECT_TRUE(passes[2].straightLink);
}

// The clearing cache hands back a plan only for exactly the same region, step, direction and
// start; what it hands back is the plan made without it.
TEST(SlCycles, ClearingCacheReusesOnlyAnIdenticalPlan) {
    const Region region = regionOf(rectangle(-25, -15, 25, 15));
    const Vec2 from(-30.0, -20.0);
    std::vector<contour::ClearingPass> fresh, first, again;
    ASSERT_FALSE(contour::planClearing(22, region, 5.0, true, from, fresh));
    contour::ClearingCache cache;
    EXPECT_EQ(cache.find(region, 5.0, true, from), nullptr);
    ASSERT_FALSE(contour::planClearing(22, region, 5.0, true, from, first, &cache));
    ASSERT_NE(cache.find(region, 5.0, true, from), nullptr);
    EXPECT_EQ(cache.find(region, 4.999, true, from), nullptr);
    EXPECT_EQ(cache.find(region, 5.0, false, from), nullptr);
    EXPECT_EQ(cache.find(region, 5.0, true, Vec2(-30.0, -19.0)), nullptr);
    EXPECT_EQ(cache.find(regionOf(rectangle(-25, -15, 25, 15.001)), 5.0, true, from), nullptr);
    ASSERT_FALSE(contour::planClearing(23, region, 5.0, true, from, again, &cache));
    ASSERT_EQ(fresh.size(), 3u);  // rings 50 x 30, 40 x 20, 30 x 10
    for (const auto* plan : {&first, &again}) {
        ASSERT_EQ(plan->size(), fresh.size());
        for (size_t i = 0; i < fresh.size(); ++i) {
            EXPECT_EQ((*plan)[i].path.segments.size(), fresh[i].path.segments.size());
            EXPECT_EQ((*plan)[i].path.segments.front().start, fresh[i].path.segments.front().start);
            EXPECT_EQ((*plan)[i].fullWidth, fresh[i].fullWidth);
        }
    }
    EXPECT_TRUE(fresh.front().fullWidth);  // the innermost ring first
    EXPECT_FALSE(fresh.back().fullWidth);
}

// posAfterContPocket (spec §1.6): ToolAxClearanceHeight ends at Q7 = 50 straight above the
// last cut (Q208 = 0: at Q12); PosBeforeMachining goes on from there back to where the tool was
// before the cycle: from (7, -3, 100) (above Q7) up to 100 first, then over (7, -3); from
// (7, -3, 30) (below Q7) over (7, -3) at 50, then down to 30, at rapid.
TEST(SlCycles, EndPositionFollowsPosAfterContPocket) {
    const CycleValues data = contourData(-10.0, 0.5, 0.5);
    CycleContext ctx = pocketWithIsland(data);
    ctx.start = {7.0, -3.0, 100.0};
    Recorder axisOnly;
    ASSERT_FALSE(run(22, roughOut(5.0), ctx, axisOnly));
    ASSERT_GE(axisOnly.moves.size(), 2u);
    const Move& lastCut = axisOnly.moves[axisOnly.moves.size() - 2];
    const Move& up = axisOnly.moves.back();
    EXPECT_EQ(up.kind, Move::Line);
    EXPECT_DOUBLE_EQ(up.feed.value, 350.0);
    EXPECT_NEAR((up.target - Vec3(lastCut.target.x(), lastCut.target.y(), 50.0)).norm(), 0.0, 1e-9);

    ctx.slReturnToStart = true;
    Recorder back;
    ASSERT_FALSE(run(22, roughOut(5.0), ctx, back));
    ASSERT_EQ(back.moves.size(), axisOnly.moves.size() + 2);
    const Move& higher = back.moves[back.moves.size() - 2];
    EXPECT_EQ(higher.kind, Move::Rapid);
    EXPECT_NEAR((higher.target - Vec3(up.target.x(), up.target.y(), 100.0)).norm(), 0.0, 1e-9);
    EXPECT_EQ(back.moves.back().kind, Move::Rapid);
    EXPECT_NEAR((back.moves.back().target - Vec3(7.0, -3.0, 100.0)).norm(), 0.0, 1e-9);

    ctx.start = {7.0, -3.0, 30.0};
    ctx.roughingRadius = 5.0;
    CycleValues side;
    const std::pair<uint16_t, double> sideValues[] = {
        {9, 1.0}, {10, 5.0}, {11, 100.0}, {12, 400.0}, {14, 0.0}};
    for (auto [q, value] : sideValues)
        side.set(q, value);
    Recorder below;
    ASSERT_FALSE(run(24, side, ctx, below));
    ASSERT_GE(below.moves.size(), 3u);
    const Move* tail = &below.moves[below.moves.size() - 3];
    EXPECT_NEAR(tail[0].target.z(), 50.0, 1e-9);
    EXPECT_EQ(tail[1].kind, Move::Rapid);
    EXPECT_NEAR((tail[1].target - Vec3(7.0, -3.0, 50.0)).norm(), 0.0, 1e-9);
    EXPECT_EQ(tail[2].kind, Move::Rapid);
    EXPECT_NEAR((tail[2].target - Vec3(7.0, -3.0, 30.0)).norm(), 0.0, 1e-9);
}

CycleValues floorFinishing() {
    CycleValues v;
    v.set(11, 100.0);
    v.set(12, 350.0);
    v.set(208, 0.0);
    return v;
}

// Cycle 23 onto the floor on a vertical quarter arc tangent to the floor and the first pass.
// A 60 x 40 pocket, R5, allowances 0.5, depth 10: tool-centre rings |u| <= 24.5, 19.5, 14.5 by
// |v| <= 14.5, 9.5, 4.5; the innermost first, from its corner nearest the contour's start
// (-30, -20), i.e. (-14.5, -4.5), along +u (counter-clockwise). The arc of radius R = 5 starts
// 5 back along -u and 5 above the floor, at (-19.5, -4.5, -5) (inside the outer ring), about
// (-14.5, -4.5, -5): reached at rapid (it lies above Q6 over the roughed floor, -9.5 + 2), it
// ends on (-14.5, -4.5, -10) going straight down at its start and along +u at its end, at Q11.
TEST(SlCycles, FloorFinishingApproachesOnAVerticalTangentialArc) {
    const CycleValues data = contourData(-10.0, 0.5, 0.5);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.contours.push_back({rectangle(-30, -20, 30, 20), false, 1});
    ctx.contourData = &data;
    Recorder out;
    ASSERT_FALSE(run(23, floorFinishing(), ctx, out));
    size_t arcs = 0;
    for (size_t i = 1; i + 1 < out.moves.size(); ++i) {
        const Move& m = out.moves[i];
        if (m.kind != Move::SpatialArc) continue;
        ++arcs;
        const Move& before = out.moves[i - 1];
        EXPECT_EQ(before.kind, Move::Rapid);
        EXPECT_NEAR((before.target - Vec3(-19.5, -4.5, -5.0)).norm(), 0.0, 1e-9);
        EXPECT_NEAR((m.from - Vec3(-19.5, -4.5, -5.0)).norm(), 0.0, 1e-9);
        EXPECT_NEAR((m.centre3 - Vec3(-14.5, -4.5, -5.0)).norm(), 0.0, 1e-9);
        EXPECT_NEAR((m.target - Vec3(-14.5, -4.5, -10.0)).norm(), 0.0, 1e-9);
        EXPECT_DOUBLE_EQ(m.feed.value, 100.0);
        // A quarter arc: its tangent at the end is -(from - centre) / r, at the start
        // (target - centre) / r.
        const Vec3 endTangent = -(m.from - m.centre3) / 5.0;
        const Vec3 startTangent = (m.target - m.centre3) / 5.0;
        EXPECT_NEAR((startTangent - Vec3(0.0, 0.0, -1.0)).norm(), 0.0, 1e-12);
        EXPECT_NEAR((endTangent - Vec3(1.0, 0.0, 0.0)).norm(), 0.0, 1e-12);
        const Move& next = out.moves[i + 1];
        EXPECT_EQ(next.kind, Move::Line);
        EXPECT_NEAR((next.target - Vec3(14.5, -4.5, -10.0)).norm(), 0.0, 1e-9);
    }
    EXPECT_EQ(arcs, 1u) << "the other rings follow at the floor";
}

// Where the arc of R has no room it is halved (R/2, R/4), else the tool goes straight down. A
// 26 x 16 pocket, R5, no allowance, Q2 = 0.5: rings |u| <= 8, 5.5 by |v| <= 3, 0.5; the inner
// one starts at (-5.5, -0.5) along +u with 2.5 behind it to the outer ring: an arc of R/2 = 2.5
// from (-8, -0.5, -7.5). A 16 x 12 pocket has one ring |u| <= 3, |v| <= 1, starting at its
// corner (-3, -1): nothing behind it, so down at Q11 from Q6 over the floor (-10 + 2).
TEST(SlCycles, FloorFinishingArcHalvedOrStraightDownWithoutRoom) {
    CycleValues data = contourData(-10.0, 0.0, 0.0);
    data.set(2, 0.5);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.contours.push_back({rectangle(-13, -8, 13, 8), false, 1});
    ctx.contourData = &data;
    Recorder halved;
    ASSERT_FALSE(run(23, floorFinishing(), ctx, halved));
    size_t arcs = 0;
    for (const Move& m : halved.moves) {
        if (m.kind != Move::SpatialArc) continue;
        ++arcs;
        EXPECT_NEAR((m.from - Vec3(-8.0, -0.5, -7.5)).norm(), 0.0, 1e-9);
        EXPECT_NEAR((m.centre3 - Vec3(-5.5, -0.5, -7.5)).norm(), 0.0, 1e-9);
        EXPECT_NEAR((m.target - Vec3(-5.5, -0.5, -10.0)).norm(), 0.0, 1e-9);
    }
    EXPECT_EQ(arcs, 1u);

    const CycleValues narrowData = contourData(-10.0, 0.0, 0.0);
    ctx.contours = {{rectangle(-8, -6, 8, 6), false, 1}};
    ctx.contourData = &narrowData;
    Recorder straight;
    ASSERT_FALSE(run(23, floorFinishing(), ctx, straight));
    std::vector<Vec3> plunge;
    for (size_t i = 1; i < straight.moves.size(); ++i) {
        EXPECT_NE(straight.moves[i].kind, Move::SpatialArc);
        if (straight.moves[i].kind == Move::Line && straight.moves[i - 1].kind == Move::Rapid) {
            plunge = {straight.moves[i - 1].target, straight.moves[i].target};
            EXPECT_DOUBLE_EQ(straight.moves[i].feed.value, 100.0);
        }
    }
    ASSERT_EQ(plunge.size(), 2u);
    EXPECT_NEAR((plunge[0] - Vec3(-3.0, -1.0, -8.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((plunge[1] - Vec3(-3.0, -1.0, -10.0)).norm(), 0.0, 1e-9);
}

// The approach arc lies in the Z/X plane (seed 000, chapter 7's overview: "spindle axis Z:
// circular path in the Z/X plane"), also where the pass starts across X. A circular pocket of
// radius 30 from (30, 0), R5, Q2 = 1: rings of radius 25, 20, 15, 10, 5; the innermost starts
// nearest (30, 0), at (5, 0), going +Y. The arc meets the floor going +X: from 5 back along X
// and 5 above the floor, (0, 0, -5), about (5, 0, -5) to (5, 0, -10); Y stays 0 (plane Z/X).
// A circle of radius 10 from (-10, 0) leaves one ring of radius 5, starting at (-5, 0) going
// -Y: +X would come from (-10, 0), outside the ring, so it comes along -X from (0, 0, -5) about
// (-5, 0, -5) to (-5, 0, -10).
TEST(SlCycles, FloorFinishingApproachArcLiesInTheZxPlane) {
    const CycleValues data = contourData(-10.0, 0.0, 0.5);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 5.0;
    const auto arcsOf = [&](const ClosedContour& pocket) {
        ctx.contours = {{pocket, false, 1}};
        ctx.contourData = &data;
        Recorder out;
        EXPECT_FALSE(run(23, floorFinishing(), ctx, out));
        std::vector<Move> arcs;
        for (const Move& m : out.moves) {
            if (m.kind == Move::SpatialArc) arcs.push_back(m);
        }
        return arcs;
    };
    const std::vector<Move> inner = arcsOf(circleContour(30.0));
    ASSERT_EQ(inner.size(), 1u);
    EXPECT_NEAR((inner[0].from - Vec3(0.0, 0.0, -5.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((inner[0].centre3 - Vec3(5.0, 0.0, -5.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((inner[0].target - Vec3(5.0, 0.0, -10.0)).norm(), 0.0, 1e-9);

    ClosedContour fromLeft;
    fromLeft.segments.push_back(PlanarSegment::arc({-10.0, 0.0}, {0.0, 0.0}, 2.0 * kPi));
    const std::vector<Move> single = arcsOf(fromLeft);
    ASSERT_EQ(single.size(), 1u);
    EXPECT_NEAR((single[0].from - Vec3(0.0, 0.0, -5.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((single[0].centre3 - Vec3(-5.0, 0.0, -5.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((single[0].target - Vec3(-5.0, 0.0, -10.0)).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace kerf::cycles
