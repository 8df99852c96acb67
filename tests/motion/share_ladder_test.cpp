#include "motion/planner/share_ladder.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "canon_builders.h"
#include "core/geometry/arc_math.h"
#include "motion/kinematics/machine_model.h"
#include "motion/planner/planner.h"
#include "tests/motion/motion_test_run.h"

// The tangential share of the axis limits along a curve that starts or ends at rest (issue 15
// part 3), or that brakes into or leaves a slow corner (issue 16): more of each axis's
// acceleration for the tangential part while the velocity, and with it the centripetal part, is
// low.
namespace kerf::motion::test {
namespace {

using kerf::test::command;
using kerf::test::pose;

TEST(ShareLadder, StagesOfAnR5CircleAtF6000MatchTheHandComputation) {
    // Built-in mill: A 2000 mm/s^2, J 1e6 mm/s^3 per axis. On a circle in XY an axis moves with
    // a = A_t sin + (v^2 / R) cos, peaking at sqrt(A_t^2 + (v^2 / R)^2) <= A: the cap of share
    // p is v = sqrt(R sqrt(A^2 - (p A)^2)). 90 %: 66.02 mm/s, 60 %: 89.44 mm/s, 30 %: 97.67 mm/s.
    // The look-ahead keeps 10 % for the rest of the circle: by the summed peaks
    // sqrt((A - p A) R) it is the first share near the feed (94.87 mm/s; 2 % is not 5 % more).
    MachineModel model = makeMachineModel(millConfig(), {});
    AxisVector from{};
    AxisVector to{};
    to[0] = 10.0;  // the opposite point of the circle about (5, 0)
    PathGeometry circle = makeHelix(from, to, {5.0, 0.0, 0.0}, Axis::X, Axis::Y, Axis::Z, kPi);
    std::array<ShareStage, 4> stages;
    ASSERT_EQ(shareLadder(model, circle, 0.005, 100.0, stages), 3u);
    EXPECT_NEAR(stages[0].cap, std::sqrt(5.0 * std::sqrt(2000.0 * 2000.0 - 1800.0 * 1800.0)), 1e-6);
    EXPECT_NEAR(stages[1].cap, std::sqrt(5.0 * std::sqrt(2000.0 * 2000.0 - 1200.0 * 1200.0)), 1e-6);
    EXPECT_NEAR(stages[2].cap, std::sqrt(5.0 * std::sqrt(2000.0 * 2000.0 - 600.0 * 600.0)), 1e-6);
    EXPECT_DOUBLE_EQ(stages[0].limits.accel, 1800.0);
    EXPECT_DOUBLE_EQ(stages[1].limits.accel, 1200.0);
    // From rest to 66.02 at 1800 mm/s^2 and 9e5 mm/s^3: v / 2 (v / A + A / J), 5 % margin.
    const double v0 = stages[0].cap;
    EXPECT_NEAR(stages[0].length, 1.05 * v0 / 2.0 * (v0 / 1800.0 + 1800.0 / 9e5), 1e-9);
    // R50 runs at its feed with 90 %: no stages.
    PathGeometry wide = makeHelix(from, {100.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
                                  {50.0, 0.0, 0.0}, Axis::X, Axis::Y, Axis::Z, kPi);
    EXPECT_EQ(shareLadder(model, wide, 0.005, 100.0, stages), 0u);
}

std::vector<canon::Command> trueCircle(double r, double length) {
    // gen.py arccircle: centre (0, r), arcs of at most a quarter turn.
    std::vector<canon::Command> commands;
    const double phi = length / r;
    const int count = static_cast<int>(std::ceil(phi / (kPi / 2.0)));
    for (int k = 1; k <= count; ++k) {
        const double s = length * k / count;
        canon::ArcMove arc;
        arc.target = pose(r * std::sin(s / r), r - r * std::cos(s / r), 0.0);
        arc.center = Vec3(0.0, r, 0.0);
        arc.plane = Plane::XY;
        arc.sweepRad = phi / count;
        arc.feed = 6000.0;
        commands.push_back(command(arc, static_cast<uint32_t>(k)));
    }
    return commands;
}

TEST(ShareLadder, TrueArcR5FromRestToRestRunsNearTheTimeOptimalBound) {
    // 100 mm of R5 at F6000 from rest to rest. Time-optimal bound along the circle: 1.0491 s
    // (shared/tools/motion/bounds.py: topp_acc(circle(5), 100, 100) + A / J). With one share
    // for each arc (10 %, 200 mm/s^2, the share that runs at the feed) it took 1.516 s (1.45x);
    // the target is 1.10x.
    TestRun run = runCommands(millConfig(), trueCircle(5.0, 100.0), Pose{});
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_FALSE(run.report.refused);
    EXPECT_LE(run.report.feedTimeS, 1.10 * 1.0491);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
}

// Cycle 24's exit from an island ring (seed chapter 9 at F6000, moves 573-575): a line along X,
// a tangent arc R2.9 of 69.3979 degrees to the left, then a line up Z (a corner of 90 degrees),
// each at F6000, from rest to rest.
std::vector<canon::Command> arcIntoACorner() {
    const double sweep = 69.3979 * kPi / 180.0;
    const double endX = 17.464 + 2.9 * std::sin(sweep);
    const double endY = 2.9 - 2.9 * std::cos(sweep);
    std::vector<canon::Command> commands;
    canon::LinearMove line{pose(17.464, 0.0, 0.0), 6000.0};
    commands.push_back(command(line, 1));
    canon::ArcMove arc;
    arc.target = pose(endX, endY, 0.0);
    arc.center = Vec3(17.464, 2.9, 0.0);
    arc.plane = Plane::XY;
    arc.sweepRad = sweep;
    arc.feed = 6000.0;
    commands.push_back(command(arc, 2));
    canon::LinearMove up{pose(endX, endY, 5.0), 6000.0};
    commands.push_back(command(up, 3));
    return commands;
}

TEST(ShareLadder, AnArcBrakesIntoASlowCornerAtTheStagesOfAStop) {
    // R2.9 at F6000 (A 2000 mm/s^2): by the summed peaks sqrt((A - p A) R) the look-ahead's
    // share is 10 % (72.25 mm/s; 2 % gives 75.39, not 5 % more), 200 mm/s^2 of braking. The
    // corner's blend (a quarter of the 0.01 mm tolerance at most off the corner) passes at a few
    // mm/s, below the 90 % stage's cap sqrt(R sqrt(A^2 - (0.9 A)^2)) = 50.28 mm/s: the arc's
    // last piece brakes at 90 % (1800 mm/s^2), as before a stop. Before 2026-11-28 the whole
    // arc kept 10 % and took 0.162 s (its bound: 0.058 s).
    MachineModel model = makeMachineModel(millConfig(), {});
    Planner planner(model);
    planner.setPosition(Pose{}.values);
    for (const canon::Command& c : arcIntoACorner())
        ASSERT_TRUE(planner.add(c));
    planner.flush();
    std::vector<MotionItem> arcPieces;
    while (auto item = planner.next()) {
        if (item->kind == MotionItem::Kind::Element && item->element.moveIndex == 2 &&
            item->element.geometry.curved())
            arcPieces.push_back(*item);
    }
    ASSERT_GE(arcPieces.size(), 2u);
    EXPECT_DOUBLE_EQ(arcPieces.front().element.limits.accel, 200.0);  // 10 %
    EXPECT_DOUBLE_EQ(arcPieces.back().element.limits.accel, 1800.0);
    EXPECT_NEAR(arcPieces.back().element.capVelocity,
                std::sqrt(2.9 * std::sqrt(2000.0 * 2000.0 - 1800.0 * 1800.0)), 1e-6);
}

TEST(ShareLadder, AnArcIntoASlowCornerRunsNearTheTimeOptimalBound) {
    // Time-optimal bound of the three moves from rest to rest: 0.3549 s (scripts/bench/
    // path_bound.py, independent of the planner: the exact line and arc at the axes' limits, the
    // corner at the apex speed of the fastest turn within the tolerance band, + A / J).
    TestRun run = runCommands(millConfig(), arcIntoACorner(), Pose{});
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_FALSE(run.report.refused);
    EXPECT_LE(run.report.feedTimeS, 1.10 * 0.3549);
    EXPECT_GE(run.report.feedTimeS, 0.3549);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
}

}  // namespace
}  // namespace kerf::motion::test
