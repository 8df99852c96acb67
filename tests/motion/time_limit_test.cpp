// The simulated-time limit of a run: a program whose motion does not end within it stops there
// with an error at the block that was moving, instead of ending silently in the middle of its
// path (found by the corpus sweep: a FAGOR G68 illustration finishing at 0.12 mm/min).
#include <gtest/gtest.h>

#include "tests/motion/motion_test_run.h"

namespace kerf::motion::test {
namespace {

canon::Command line(double x, double feedMmPerMin, uint32_t sourceLine) {
    Pose target;
    target[Axis::X] = x;
    canon::Command c;
    c.location.line = sourceLine;
    c.body = canon::LinearMove{target, feedMmPerMin};
    return c;
}

// 100 mm at 60 mm/min (1 mm/s): 100 s of feed, then 10 mm more.
std::vector<canon::Command> slowLines() {
    return {line(100.0, 60.0, 3), line(110.0, 60.0, 4)};
}

bool hasTimeLimitError(const MotionReport& report, uint32_t& line) {
    for (const Diagnostic& d : report.diagnostics) {
        if (d.code == "motion.time-limit" && d.severity == Severity::Error) {
            line = d.line;
            return true;
        }
    }
    return false;
}

TEST(SimulatedTimeLimit, AMotionLongerThanTheLimitStopsWithAnErrorAtItsBlock) {
    SimulationOptions options;
    options.maxSimulatedS = 10.0;
    TestRun run = runCommands(millConfig(), slowLines(), Pose{}, options);
    uint32_t at = 0;
    ASSERT_TRUE(hasTimeLimitError(run.report, at));
    EXPECT_EQ(at, 3u);  // the first line was moving
    EXPECT_TRUE(run.sim->halted());
    // 10 s at 1 mm/s, less the few milliseconds of acceleration: about 10 mm of the 100.
    EXPECT_GT(run.report.finalPosition[0], 9.9);
    EXPECT_LT(run.report.finalPosition[0], 10.01);
}

TEST(SimulatedTimeLimit, AMotionWithinTheLimitEndsWithoutError) {
    SimulationOptions options;
    options.maxSimulatedS = 200.0;
    TestRun run = runCommands(millConfig(), slowLines(), Pose{}, options);
    uint32_t at = 0;
    EXPECT_FALSE(hasTimeLimitError(run.report, at));
    EXPECT_FALSE(run.sim->halted());
    EXPECT_NEAR(run.report.finalPosition[0], 110.0, 1e-6);
    // 110 mm at 1 mm/s.
    EXPECT_NEAR(run.report.durationS, 110.0, 0.5);
}

}  // namespace
}  // namespace kerf::motion::test
