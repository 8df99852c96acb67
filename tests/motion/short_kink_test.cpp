// Blending across a short kinked segment (planner.h, blendAcrossShort): a 0.02 mm step between two
// long lines, and the default mill on the 0.02 mm gen_nc raster at F6000 (issue 4's criterion),
// whose U-turns end in such a step. Limits, tolerance and end position by the independent
// SampleChecker; speeds and times against values worked out by hand or by the FIGURES bound.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "tests/motion/bench/raster_bound.h"
#include "tests/motion/motion_test_run.h"
#include "tests/motion/raster_program.h"

namespace kerf::motion::test {
namespace {

Pose pose(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

canon::Command line(const Pose& target, uint32_t number) {
    canon::Command command;
    command.location.line = number;
    command.body = canon::LinearMove{target, 6000.0};
    return command;
}

struct Collect final : canon::Sink {
    std::vector<canon::Command> commands;
    void consume(const canon::Command& c) override { commands.push_back(c); }
};

TEST(ShortKink, OneBlendAcrossTheStepInsteadOfTwoTightCorners) {
    // 2 mm along X, a step of 0.006 mm up over 0.02 mm (16.7 degrees), 2 mm along X. Blended
    // corner by corner, each blend may use half the step (0.01 mm): radius 0.01 / tan(8.35 deg)
    // = 0.068 mm, at most sqrt(2000 * 0.068) = 11.7 mm/s at the mill's 2000 mm/s^2. Across the
    // step the turn is an S over up to 1 mm on either side, within the tolerance.
    std::vector<canon::Command> commands = {line(pose(2.0, 0.0, 0.0), 1),
                                            line(pose(2.02, 0.0, 0.006), 2),
                                            line(pose(4.02, 0.0, 0.006), 3)};
    double slowest = 1e300;
    TestRun run = runCommands(millConfig(), commands, pose(0.0, 0.0, 0.0), {},
                              [&](SimulatedMachine&, const Sample& sample, const MotionStatus&) {
                                  if (std::fabs(sample.tip[0] - 2.01) < 0.2)
                                      slowest = std::min(slowest, sample.pathVelocity);
                              });
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_FALSE(run.report.refused);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
    EXPECT_GT(slowest, 2.0 * 11.7);
    EXPECT_NEAR(run.report.finalPosition[0], 4.02, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[2], 0.006, 1e-6);
}

TEST(ShortKink, AStepBeyondTheToleranceKeepsItsCorners) {
    // 0.02 mm up over 0.02 mm: an S within 0.005 mm of that cannot get past the step, so the
    // path still turns at both of its corners and ends exactly.
    std::vector<canon::Command> commands = {line(pose(2.0, 0.0, 0.0), 1),
                                            line(pose(2.02, 0.0, 0.02), 2),
                                            line(pose(4.02, 0.0, 0.02), 3)};
    TestRun run = runCommands(millConfig(), commands, pose(0.0, 0.0, 0.0));
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
    EXPECT_NEAR(run.report.finalPosition[2], 0.02, 1e-6);
}

TEST(ShortKink, DefaultMillRunsTheFineRasterWithin115PercentOfTheBound) {
    // Issue 4: 5,000 segments of 0.02 mm at F6000 on the mill as shipped, within 1.15x of the
    // FIGURES acceleration bound at the mill's 2000 mm/s^2 (rows trapezoidal, U-turns at
    // sqrt(2000 * 0.25) = 22.4 mm/s).
    RasterOptions options;
    options.blocks = 5000;
    options.segMm = 0.02;
    options.feedMmPerMin = 6000.0;
    Collect collect;
    emitRaster(options, collect);
    TestRun run = runCommands(millConfig(), collect.commands, rasterStart());
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
    EXPECT_LE(run.report.feedTimeS, 1.15 * rasterBoundS(options, 2000.0));
}

}  // namespace
}  // namespace kerf::motion::test
