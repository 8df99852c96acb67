// The report's machining time comes from the planner and the servo cycle in simulated time: it
// equals the simulated program run (`kerf run --motion`) on both built-in machines. Before, it was
// length / feed without acceleration: 26.70 s against 27.80 s on the mill program, 59.44 s
// against 47.29 s on the lathe's (it took G96's speed at the start of each move).
#include <gtest/gtest.h>

#include "tests/support/machining_time_programs.h"
#include "tests/support/test_paths.h"

namespace kerf::app {
namespace {

TEST(MachiningTime, ReportEqualsTheSimulatedProgramRunOnTheMill) {
    const auto dir = test::uniqueTempDir("machining_time_mill");
    const double program =
        test::simulatedProgramRunS(dir / "T.H", test::kMillTimingProgram, "mill");
    const nlohmann::json report =
        test::runReport(dir / "T.H", test::kMillTimingProgram, "mill", false);
    ASSERT_TRUE(report["ok"].get<bool>());
    const double machining = report["machining_time_s"].get<double>();
    EXPECT_NEAR(machining, program, 0.01 * program);
    // Never faster than the programmed feeds and the dwell.
    EXPECT_GT(machining, test::kMillFeedAndDwellS);
}

TEST(MachiningTime, ReportEqualsTheSimulatedProgramRunOnTheLathe) {
    const auto dir = test::uniqueTempDir("machining_time_lathe");
    const double program =
        test::simulatedProgramRunS(dir / "T.PIT", test::kLatheTimingProgram, "lathe");
    const nlohmann::json report =
        test::runReport(dir / "T.PIT", test::kLatheTimingProgram, "lathe", false);
    ASSERT_TRUE(report["ok"].get<bool>());
    EXPECT_NEAR(report["machining_time_s"].get<double>(), program, 0.01 * program);
    // The dwells alone take 2 s (K150 and K50: hundredths of a second).
    EXPECT_GT(program, 2.0);
}

}  // namespace
}  // namespace kerf::app
