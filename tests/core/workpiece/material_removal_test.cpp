#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "core/workpiece/cut_recorder.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {
namespace {

constexpr double kBall = 2.0;  // probe ball radius
const Cutter kD10{5.0, 0.0, 60.0};

// A 100 x 60 x 40 block, top at z 0, with what `removed` holds cut out of it.
SimulatedWorkpiece block(std::shared_ptr<const RemovedMaterial> removed, Placement placement = {}) {
    SimulatedWorkpiece part(placement);
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    part.setRemoved(std::move(removed));
    return part;
}

TEST(ToolSweep, FlatCutterAlongAPlanarLineIsAStadiumExtruded) {
    const Sweep s = sweepAlongLine(kD10, Vec3(0, 0, -5), Vec3(20, 0, -5));
    EXPECT_NEAR(sweepDistance(s, Vec3(10, 8, 0)), 3.0, 1e-12);    // side
    EXPECT_NEAR(sweepDistance(s, Vec3(24, 3, 0)), 0.0, 1e-12);    // round end: 5 from (20, 0)
    EXPECT_NEAR(sweepDistance(s, Vec3(10, 0, -7)), 2.0, 1e-12);   // below the flat bottom
    EXPECT_NEAR(sweepDistance(s, Vec3(10, 0, -4)), -1.0, 1e-12);  // 1 above the bottom
}

TEST(ToolSweep, BallCutterHasARoundBottom) {
    const Cutter ball{5.0, 5.0, 60.0};
    const Sweep s = sweepAlongLine(ball, Vec3(0, 0, -10), Vec3(0, 0, -10));
    // The ball's centre is 5 above the tip: (0, 0, -5); a point 3 off the axis at the tip's
    // height is sqrt(9 + 25) - 5 from it.
    EXPECT_NEAR(sweepDistance(s, Vec3(3, 0, -10)), std::sqrt(34.0) - 5.0, 1e-12);
    const Cutter torus{5.0, 1.0, 60.0};
    const Sweep t = sweepAlongLine(torus, Vec3(0, 0, -10), Vec3(0, 0, -10));
    // Below the torus's flat part (radius 4): straight down to the tip plane.
    EXPECT_NEAR(sweepDistance(t, Vec3(3, 0, -11)), 1.0, 1e-12);
    // Beside the corner: the corner circle's centre is at radius 4, 1 above the tip.
    EXPECT_NEAR(sweepDistance(t, Vec3(7, 0, -9)), 2.0, 1e-12);
}

TEST(ToolSweep, SlopedLineIsTheUnionOfTheCutterOnIt) {
    // A ramp from (0, 0, 0) to (20, 0, -10). In the section y = 0 the flat bottom's left end
    // (x = tip - 5) traces the line from (-5, 0) to (15, -10), x + 2 z + 5 = 0, the lowest edge
    // there; the point (10, -15) is 15 / sqrt(5) from it, its foot (13, -9) on that edge.
    const Sweep s = sweepAlongLine(kD10, Vec3(0, 0, 0), Vec3(20, 0, -10));
    EXPECT_NEAR(sweepDistance(s, Vec3(10, 0, -15)), 15.0 / std::sqrt(5.0), 1e-9);
    // Beside it in y, level with the tip at x = 10 (z -5): 3 beyond the cutter's side.
    EXPECT_NEAR(sweepDistance(s, Vec3(10, 8, -4)), 3.0, 1e-9);
}

TEST(ToolSweep, ArcIsAnAnnularSector) {
    // A quarter from angle 0 to 90 degrees about the origin, radius 20, at z -5.
    const Sweep s =
        sweepAlongArc(kD10, ArcSweep{Vec2(0, 0), -5.0, 20.0, 0.0, std::numbers::pi / 2});
    EXPECT_NEAR(sweepDistance(s, Vec3(30 / std::sqrt(2.0), 30 / std::sqrt(2.0), 0)), 5.0, 1e-12);
    EXPECT_NEAR(sweepDistance(s, Vec3(10 / std::sqrt(2.0), 10 / std::sqrt(2.0), 0)), 5.0, 1e-12);
    // Past the end at (20, 0): beside the end point, in -y.
    EXPECT_NEAR(sweepDistance(s, Vec3(20, -9, 0)), 4.0, 1e-12);
    // Clockwise: the same quarter traversed backwards from 90 to 0 degrees.
    const Sweep cw = sweepAlongArc(
        kD10, ArcSweep{Vec2(0, 0), -5.0, 20.0, std::numbers::pi / 2, -std::numbers::pi / 2});
    EXPECT_NEAR(sweepDistance(cw, Vec3(20, -9, 0)), 4.0, 1e-12);
    EXPECT_NEAR(sweepDistance(cw, Vec3(-9, 20, 0)), 4.0, 1e-12);
    EXPECT_NEAR(sweepDistance(cw, Vec3(-20, 0, 0)), std::hypot(20.0, 20.0) - 5.0, 1e-12);
}

TEST(MaterialRemoval, DrilledHoleIsTouchedAtItsWallAndFloor) {
    auto removed = std::make_shared<RemovedMaterial>();
    removed->addLine(kD10, Vec3(30, 20, 2), Vec3(30, 20, -15));
    const SimulatedWorkpiece part = block(removed);
    // From the hole's centre at z -5 along +x: the wall at 35, the ball centre 2 before.
    auto hit = part.touch(Vec3(30, 20, -5), Vec3(1, 0, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), 33.0, 1e-9);
    // Down onto the floor at -15.
    hit = part.touch(Vec3(30, 20, -5), Vec3(0, 0, -1), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z(), -13.0, 1e-9);
    EXPECT_FALSE(part.touches(Vec3(30, 20, -5), kBall));
    EXPECT_TRUE(part.touches(Vec3(30, 20, -5), 5.5));
}

TEST(MaterialRemoval, TheCutsAreWhereTheToolWasNotWhereThePartWasProgrammed) {
    // The part lies shifted and turned; the tool cut at (30, 20) of the touches' coordinates,
    // so the hole is there whatever the placement.
    auto removed = std::make_shared<RemovedMaterial>();
    removed->addLine(kD10, Vec3(30, 20, 2), Vec3(30, 20, -15));
    const SimulatedWorkpiece part = block(removed, {Vec3(1.5, -0.8, -0.2), 0.7, Vec3::Zero()});
    auto hit = part.touch(Vec3(30, 20, -5), Vec3(0, -1, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->y(), 17.0, 1e-9);
}

TEST(MaterialRemoval, FullCircleGivesAnExactBore) {
    // A bore of diameter 20: a plunge at the centre, then the D10 tool's centre on a full
    // circle of radius 5 at z -10 (a disc of radius 10 in the plane).
    auto removed = std::make_shared<RemovedMaterial>();
    removed->addLine(kD10, Vec3(50, 30, 2), Vec3(50, 30, -10));
    removed->addLine(kD10, Vec3(50, 30, -10), Vec3(55, 30, -10));
    removed->addArc(kD10, Vec3(55, 30, -10), Vec3(55, 30, -10), Vec3(50, 30, -10), Plane::XY,
                    2 * std::numbers::pi);
    const SimulatedWorkpiece part = block(removed);
    for (double deg : {0.0, 37.0, 90.0, 200.0, 315.0}) {
        const double a = deg * std::numbers::pi / 180.0;
        const Vec3 dir(std::cos(a), std::sin(a), 0.0);
        auto hit = part.touch(Vec3(50, 30, -5), dir, 30.0, kBall);
        ASSERT_TRUE(hit) << deg;
        EXPECT_NEAR((*hit - Vec3(50, 30, -5)).norm(), 8.0, 1e-9) << deg;
    }
    // A ball larger than the cutter's radius still fits: 10 - 6 = 4 from the centre.
    auto hit = part.touch(Vec3(50, 30, -3), Vec3(0, 1, 0), 30.0, 6.0);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->y(), 34.0, 1e-9);
}

TEST(MaterialRemoval, BallWiderThanEachSweepIsNotStoppedWhereTheyMeet) {
    // A slot 16 wide from two overlapping D10 passes at y 30 and y 36 (walls at 25 and 41). A
    // ball of radius 6 in the middle lies at most 2 deep in either pass, but it is free: it
    // moves along +y until 6 short of the wall at 41.
    auto removed = std::make_shared<RemovedMaterial>();
    removed->addLine(kD10, Vec3(10, 30, -10), Vec3(90, 30, -10));
    removed->addLine(kD10, Vec3(10, 36, -10), Vec3(90, 36, -10));
    const SimulatedWorkpiece part = block(removed);
    EXPECT_FALSE(part.touches(Vec3(50, 33, -3), 6.0));
    auto hit = part.touch(Vec3(50, 33, -3), Vec3(0, 1, 0), 20.0, 6.0);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->y(), 35.0, 0.002);  // the bound; 0.0011 short here
    EXPECT_TRUE(part.touches(Vec3(50, 33, -3), 8.5));
}

TEST(MaterialRemoval, HelixIsChordedWithinItsTolerance) {
    // One helical turn of radius 15 from z 0 to z -10 (an annulus from 10 to 20 about the
    // centre): at 270 degrees the tip passes at z -7.5; at z -3, outwards from the path, the
    // outer wall lies between 20 - tolerance and 20 from the centre.
    auto removed = std::make_shared<RemovedMaterial>();
    removed->addArc(kD10, Vec3(65, 30, 0), Vec3(65, 30, -10), Vec3(50, 30, 0), Plane::XY,
                    2 * std::numbers::pi);
    const SimulatedWorkpiece part = block(removed);
    auto hit = part.touch(Vec3(50, 15, -3), Vec3(0, -1, 0), 30.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_LE(30.0 - hit->y(), 18.0 + 1e-9);
    EXPECT_GE(30.0 - hit->y(), 18.0 - RemovedMaterial::kChordTolerance - 1e-9);
}

TEST(MaterialRemoval, StudLeftStandingInAPocketIsTouchedFromOutside) {
    // A ring pocket round a stud of diameter 20 at (50, 30): the D10 tool on a circle of
    // radius 15, depth 10.
    auto removed = std::make_shared<RemovedMaterial>();
    removed->addLine(kD10, Vec3(65, 30, 2), Vec3(65, 30, -10));
    removed->addArc(kD10, Vec3(65, 30, -10), Vec3(65, 30, -10), Vec3(50, 30, -10), Plane::XY,
                    -2 * std::numbers::pi);
    const SimulatedWorkpiece part = block(removed);
    // From above the stud's side, down to z -5 is free (the ring), then inwards along -x.
    auto hit = part.touch(Vec3(64, 30, -5), Vec3(-1, 0, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), 62.0, 1e-9);
    // Outwards to the ring's outer wall at radius 20.
    hit = part.touch(Vec3(64, 30, -5), Vec3(1, 0, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), 68.0, 1e-9);
}

TEST(CutRecorder, FollowsTheStreamAndTheProbeCutsNothing) {
    CutRecorder recorder;
    recorder.setPosition(Vec3(0, 0, 100));
    auto send = [&](canon::CommandBody body) { recorder.consume({{}, std::move(body)}); };
    canon::ToolGeometry d10;
    d10.radiusMm = 5.0;
    d10.lengthMm = 60.0;
    send(canon::ToolChange{5, "MILL", d10, Axis::Z});
    Pose above;
    above.setXyz(Vec3(30, 20, 2));
    Pose bottom;
    bottom.setXyz(Vec3(30, 20, -15));
    send(canon::RapidMove{above});
    send(canon::LinearMove{bottom, 100.0});
    send(canon::RapidMove{above});
    canon::ToolGeometry probe;
    probe.radiusMm = 2.0;
    probe.lengthMm = 50.0;
    recorder.addProbeTool(1);
    send(canon::ToolChange{1, "TS", probe, Axis::Z});
    Pose through;
    through.setXyz(Vec3(80, 40, -20));  // through the material: a probe does not cut
    send(canon::LinearMove{through, 100.0});
    const SimulatedWorkpiece part = block(recorder.removed());
    EXPECT_FALSE(part.touches(Vec3(30, 20, -12.9), kBall));  // in the hole above its floor
    EXPECT_TRUE(part.touches(Vec3(30, 20, -13.1), kBall));
    EXPECT_TRUE(part.touches(Vec3(80, 40, -20), kBall));
}

TEST(MaterialRemoval, ThousandsOfSweepsStayFast) {
    // 100 rows of 40 slots each over the block's top, then touches in one of the slots.
    auto removed = std::make_shared<RemovedMaterial>();
    const Cutter d2{1.0, 0.0, 30.0};
    for (int row = 0; row < 100; ++row) {
        for (int i = 0; i < 40; ++i) {
            const double x = 2.5 * i;
            const double y = 0.6 * row;
            removed->addLine(d2, Vec3(x, y, -1), Vec3(x + 2.5, y, -1));
        }
    }
    EXPECT_EQ(removed->size(), 4000u);
    const SimulatedWorkpiece part = block(removed);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 1000; ++i) {
        auto hit = part.touch(Vec3(50, 30, 10), Vec3(0, 0, -1), 20.0, 0.5);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->z(), -0.5, 1e-9);  // the slots' floor at -1
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 2.0);  // a thousand touches among 4000 sweeps
}

TEST(MaterialRemoval, KeepsABoundedNumberOfSweepsAndSaysSo) {
    RemovedMaterial removed;
    const Cutter d2{1.0, 0.0, 30.0};
    for (size_t i = 0; i < RemovedMaterial::kMaxSweeps; ++i)
        removed.addLine(d2, Vec3(0, 0, -1), Vec3(1, 0, -1));
    EXPECT_FALSE(removed.overflowed());
    removed.addLine(d2, Vec3(50, 30, -1), Vec3(51, 30, -1));
    EXPECT_TRUE(removed.overflowed());
    EXPECT_EQ(removed.size(), RemovedMaterial::kMaxSweeps);
    EXPECT_EQ(removed.depth(Vec3(50.5, 30, -0.5)), -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace kerf::workpiece
