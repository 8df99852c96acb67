// Cylinder-surface cycles 27, 28, 29, 39 expanded on the development, and the map from the
// development to the rotary table and the linear axes. Expected values derived by hand in the
// comments.
#include "core/cycles/cylinder/cylinder_surface.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/cycles/cycle_registry.h"

namespace kerf::cycles {
namespace {

constexpr double kPi = std::numbers::pi;
using cylinder::CylinderPlacement;
using cylinder::placeOnCylinder;

struct Move {
    bool arc = false;
    bool rapid = false;
    Vec3 target;
    Vec2 centre;
    double sweep = 0.0;
};

struct Recorder final : CycleEmitter {
    std::vector<Move> moves;
    void rapid(const Vec3& t) override { moves.push_back({false, true, t, Vec2::Zero(), 0.0}); }
    void line(const Vec3& t, const Feed&) override {
        moves.push_back({false, false, t, Vec2::Zero(), 0.0});
    }
    void arc(const Vec3& t, const Vec2& c, double s, const Feed&) override {
        moves.push_back({true, false, t, c, s});
    }
    void threadMove(const Vec3&, double, double) override {}
    void dwell(double) override {}
    void spindle(canon::SpindleDirection, double) override {}
    void orientSpindle(double) override {}
    void miscFunction(int) override {}
};

// Tool D7 (the seed's), spindle on, one open line from (0, 0) along the cylinder axis to v 30.
CycleContext lineContext(int side, Vec2 end = {0.0, 30.0}) {
    CycleContext ctx;
    ctx.start = {5.0, 5.0, 100.0};
    ctx.tool.radius = 3.5;
    ctx.spindle = canon::SpindleDirection::Clockwise;
    ctx.train.segments = {PlanarSegment::line({0.0, 0.0}, end)};
    ctx.train.side = side;
    ctx.train.labelCount = 1;
    ctx.train.label = 1;
    return ctx;
}

CycleValues values(double depth, double width = 10.0) {
    CycleValues v;
    const std::pair<uint16_t, double> list[] = {{1, depth},  {3, 0.0},    {6, 5.0},   {10, 4.0},
                                                {11, 100.0}, {12, 300.0}, {16, 20.0}, {17, 1.0},
                                                {20, width}, {21, 0.0}};
    for (auto [q, value] : list)
        v.set(q, value);
    return v;
}

std::optional<CycleError> run(int cycle, const CycleValues& v, const CycleContext& ctx,
                              Recorder& out) {
    CyclePath path(out, ctx.start);
    return findCycle(cycle)->expand(v, ctx, path);
}

void expectNear(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x(), b.x(), 1e-9);
    EXPECT_NEAR(a.y(), b.y(), 1e-9);
    EXPECT_NEAR(a.z(), b.z(), 1e-9);
}

// mill4: the A table along X through the origin, the tool along Z, radius 20. A quarter of the
// circumference (20 pi / 2 = 31.4159 mm) is a quarter turn; v runs along X; the tip stands at
// the radius plus the height: 20 - 2 = 18.
TEST(CylinderMapping, ArcLengthTurnsTheTableAndVRunsAlongItsAxis) {
    CylinderPlacement p;
    p.radiusMm = 20.0;
    const auto pose = placeOnCylinder(p, {10.0 * kPi, 10.0, -2.0}, nullptr);
    EXPECT_NEAR(pose.angleDeg, 90.0, 1e-9);
    expectNear(pose.linear, {10.0, 0.0, 18.0});
}

// Aligned: a chain along v at u 0. The point 3 mm beside it keeps the table at 0 and moves the
// tool sideways along axis x tool = X x Z = -Y: Y -3 (material at +u turns under the tool when
// A turns positive: the workpiece point under the tool at A = t is Rot_X(t) Z = (0, -sin t, ...)).
TEST(CylinderMapping, AlignedPointsTurnToTheChainAndShiftTheToolSideways) {
    CylinderPlacement p;
    p.radiusMm = 20.0;
    const cylinder::Chain chain{PlanarSegment::line({0.0, 0.0}, {0.0, 50.0})};
    const auto pose = placeOnCylinder(p, {3.0, 20.0, -1.0}, &chain);
    EXPECT_NEAR(pose.angleDeg, 0.0, 1e-9);
    expectNear(pose.linear, {20.0, -3.0, 19.0});
}

// The nearest point of an arc (centre 0, radius 10, from (10, 0) a quarter turn to (0, 10)) to
// (-5, 5) lies outside its sweep: the end (0, 10) at 7.07 beats the start at 15.8.
TEST(CylinderMapping, NearestPointOfAnArcOutsideItsSweepIsAnEnd) {
    const cylinder::Chain chain{PlanarSegment::arc({10.0, 0.0}, {0.0, 0.0}, kPi / 2.0)};
    const Vec2 n = cylinder::nearestOnChain(chain, {-5.0, 5.0});
    EXPECT_NEAR(n.x(), 0.0, 1e-9);
    EXPECT_NEAR(n.y(), 10.0, 1e-9);
    const Vec2 on = cylinder::nearestOnChain(chain, {20.0, 20.0});  // at 45 deg on the arc
    EXPECT_NEAR(on.x(), 10.0 / std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(on.y(), 10.0 / std::sqrt(2.0), 1e-9);
}

// Q17 = 0: X in degrees; 90 deg on radius 20 is 31.4159 mm. A degree arc becomes chords whose
// points lie on the scaled ellipse.
TEST(CylinderMapping, DegreesBecomeArcLengths) {
    ContourTrain train;
    train.segments = {PlanarSegment::line({0.0, 10.0}, {90.0, 10.0}),
                      PlanarSegment::arc({90.0, 10.0}, {90.0, 20.0}, kPi / 2.0)};
    const ContourTrain mm = cylinder::unrolledInMm(train, 20.0, true, 0.001);
    ASSERT_GE(mm.segments.size(), 3u);
    EXPECT_NEAR(mm.segments[0].end.x(), 10.0 * kPi, 1e-9);
    EXPECT_NEAR(mm.segments[0].length(), 10.0 * kPi, 1e-9);
    // The quarter arc ends at (100 deg, 20): 100 * 20 pi / 180 mm.
    EXPECT_NEAR(mm.segments.back().end.x(), 100.0 * 20.0 * kPi / 180.0, 1e-9);
    EXPECT_NEAR(mm.segments.back().end.y(), 20.0, 1e-9);
    for (const PlanarSegment& s : mm.segments)
        EXPECT_EQ(s.kind, PlanarSegment::Kind::Line);
    EXPECT_EQ(cylinder::unrolledInMm(train, 20.0, false, 0.001).segments.size(), 2u);
}

// Cycle 27, R0, a slot along the circumference of 10 pi mm (90 deg on radius 20), depth 2 in one
// infeed: down at the start, one milling move as long as the arc on the cylinder, up to Q6.
TEST(CylinderSurfaceCycles, Cycle27MillsTheUnrolledLengthAtTheDepth) {
    CycleContext ctx = lineContext(0, {10.0 * kPi, 0.0});
    Recorder out;
    ASSERT_FALSE(run(27, values(-2.0), ctx, out));
    ASSERT_EQ(out.moves.size(), 5u);
    expectNear(out.moves[0].target, {0.0, 0.0, 100.0});        // over the start at its height
    expectNear(out.moves[1].target, {0.0, 0.0, 5.0});          // to the set-up clearance
    expectNear(out.moves[2].target, {0.0, 0.0, -2.0});         // plunge
    expectNear(out.moves[3].target, {10.0 * kPi, 0.0, -2.0});  // 31.4159 mm: the quarter arc
    expectNear(out.moves[4].target, {10.0 * kPi, 0.0, 5.0});
}

// Cycle 28, RL, slot 10 wide, tool D7: the walls 5 - 3.5 = 1.5 beside the centre line. RL mills
// the right wall (u +1.5) forward, turns about the end to u -1.5 counter-clockwise, comes back,
// and closes round the start; tangential half circles on and off at the centre point.
TEST(CylinderSurfaceCycles, Cycle28MillsBothWallsRoundTheCentreLine) {
    CycleContext ctx = lineContext(1);
    Recorder out;
    ASSERT_FALSE(run(28, values(-4.0), ctx, out));
    // over (0, 0), down to the clearance, plunge, approach, right wall, cap, left wall, cap,
    // depart, up
    ASSERT_EQ(out.moves.size(), 10u);
    expectNear(out.moves[1].target, {0.0, 0.0, 5.0});
    expectNear(out.moves[2].target, {0.0, 0.0, -4.0});
    EXPECT_TRUE(out.moves[3].arc);
    EXPECT_NEAR(out.moves[3].sweep, kPi, 1e-9);
    expectNear(out.moves[3].target, {1.5, 0.0, -4.0});
    expectNear(out.moves[4].target, {1.5, 30.0, -4.0});
    EXPECT_NEAR(out.moves[5].sweep, kPi, 1e-9);
    EXPECT_NEAR(out.moves[5].centre.y(), 30.0, 1e-9);
    expectNear(out.moves[5].target, {-1.5, 30.0, -4.0});
    expectNear(out.moves[6].target, {-1.5, 0.0, -4.0});
    expectNear(out.moves[7].target, {1.5, 0.0, -4.0});
    expectNear(out.moves[8].target, {0.0, 0.0, -4.0});  // back at the plunging point
}

// Q21: once more round the slot at the full depth: approach, four elements, departure (the
// plunge to the depth it is at emits nothing).
TEST(CylinderSurfaceCycles, Cycle28ToleranceAddsAPassAtTheFullDepth) {
    CycleContext ctx = lineContext(1);
    CycleValues v = values(-4.0);
    v.set(21, 0.02);
    Recorder out;
    ASSERT_FALSE(run(28, v, ctx, out));
    EXPECT_EQ(out.moves.size(), 10u + 6u);
}

// Cycle 29, RL, ridge 10 wide, tool D7: the tool 5 + 3.5 = 8.5 beside the centre line, on the
// left; it starts 5 + 7 = 12 beside the first point and goes round the ridge clockwise.
TEST(CylinderSurfaceCycles, Cycle29GoesRoundTheRidgeFromBesideItsStart) {
    CycleContext ctx = lineContext(1);
    Recorder out;
    ASSERT_FALSE(run(29, values(-4.0), ctx, out));
    expectNear(out.moves[0].target, {-12.0, 0.0, 100.0});
    expectNear(out.moves[3].target, {-8.5, 0.0, -4.0});  // tangential half circle
    EXPECT_NEAR(out.moves[3].sweep, kPi, 1e-9);
    expectNear(out.moves[4].target, {-8.5, 30.0, -4.0});
    EXPECT_NEAR(out.moves[5].sweep, -kPi, 1e-9);  // clockwise about the end
    expectNear(out.moves[5].target, {8.5, 30.0, -4.0});
    expectNear(out.moves[8].target, {-12.0, 0.0, -4.0});  // departed to the start
}

// Cycle 39, RL: the contour itself with the tool 3.5 to its left; start and end the tool
// diameter (7) beside the first and the last point.
TEST(CylinderSurfaceCycles, Cycle39FollowsTheContourFromATangentialApproach) {
    CycleContext ctx = lineContext(1);
    Recorder out;
    ASSERT_FALSE(run(39, values(-4.0), ctx, out));
    expectNear(out.moves[0].target, {-7.0, 0.0, 100.0});
    expectNear(out.moves[3].target, {-3.5, 0.0, -4.0});
    expectNear(out.moves[4].target, {-3.5, 30.0, -4.0});
    expectNear(out.moves[5].target, {-7.0, 30.0, -4.0});
}

TEST(CylinderSurfaceCycles, ErrorsNameTheProblem) {
    Recorder out;
    CycleContext none = lineContext(1);
    none.train.labelCount = 0;
    EXPECT_EQ(run(27, values(-4.0), none, out)->code, "cycle-contour");  // no cycle 14
    CycleValues noRadius = values(-4.0);
    noRadius.set(16, 0.0);
    EXPECT_EQ(run(27, noRadius, lineContext(1), out)->code, "cycle-contour");
    CycleContext closed = lineContext(1);
    closed.train.closed = true;
    EXPECT_EQ(run(28, values(-4.0), closed, out)->code, "cycle-contour");
    EXPECT_EQ(run(28, values(-4.0, 5.0), lineContext(1), out)->code, "cycle-tool");  // 7 > 5
    EXPECT_EQ(run(29, values(-4.0), lineContext(0), out)->code, "cycle-contour");    // R0
    CycleContext stopped = lineContext(1);
    stopped.spindle = canon::SpindleDirection::Stopped;
    EXPECT_EQ(run(39, values(-4.0), stopped, out)->code, "cycle-spindle");
    out.moves.clear();
    EXPECT_FALSE(run(27, values(0.0), lineContext(1), out));  // depth 0: nothing
    EXPECT_TRUE(out.moves.empty());
}

}  // namespace
}  // namespace kerf::cycles
