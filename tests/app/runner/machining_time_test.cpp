// The report's machining time comes from the planner and the servo cycle in simulated time: it
// equals the simulated program run (`kerf run --motion`) on both built-in machines. Before, it was
// length / feed without acceleration: 26.70 s against 27.80 s on the mill program, 59.44 s
// against 47.29 s on the lathe's (it took G96's speed at the start of each move).
#include <optional>

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

// Real programs: a CAM post-processor's program of the shared HEIDENHAIN corpus (CIRSTUD.h: M91
// moves, a program stop, SYSREAD of the blank, 2.5 mm infeeds in a loop, full circles, rapids
// between them) on the mill, and a FAGOR G68 roughing cycle over a profile of lines and an arc
// (tests/golden, G95 feed per revolution) on the lathe. The report's machining time (no
// --motion) against the program run in simulated time (--motion), with the same options: an
// M91 move's length depends on the work offset (with Z-300 for the run and none for the report,
// CIRSTUD's times differ by 2.5 %).
struct RealProgramTimes {
    double machining = 0.0;
    double programRun = 0.0;
};

RealProgramTimes timesOf(const std::filesystem::path& program, const std::string& machine,
                         const std::optional<std::string>& workOffset, const std::string& name) {
    RealProgramTimes times;
    for (bool motion : {false, true}) {
        const auto dir = test::uniqueTempDir(name + (motion ? "_motion" : "_report"));
        app::RunOptions options;
        options.program = program;
        options.machine = machine;
        options.motion = motion;
        options.workOffset = workOffset;
        options.reportFile = dir / "report.json";
        options.stateDir = dir / "state";
        std::ostringstream diagnostics;
        EXPECT_EQ(app::runProgramCommand(options, diagnostics), 0) << diagnostics.str();
        std::ifstream in(*options.reportFile);
        const nlohmann::json report = nlohmann::json::parse(in);
        EXPECT_TRUE(report["ok"].get<bool>()) << diagnostics.str();
        if (motion)
            times.programRun = report["motion"]["duration_s"].get<double>();
        else
            times.machining = report["machining_time_s"].get<double>();
    }
    return times;
}

TEST(MachiningTime, ReportEqualsTheProgramRunOnARealMillProgram) {
    const std::filesystem::path shared = test::sharedDir();
    ASSERT_FALSE(shared.empty()) << "shared corpus not found: set KERF_SHARED_DIR";
    const RealProgramTimes times =
        timesOf(shared / "corpus/heidenhain/aamorim1913__AptPostProcessor__machine-code__CIRSTUD.h",
                "mill", "Z-300", "machining_time_corpus_mill");
    EXPECT_NEAR(times.machining, times.programRun, 0.01 * times.programRun);
    EXPECT_GT(times.programRun, 1.0);
}

TEST(MachiningTime, ReportEqualsTheProgramRunOnARealLatheProgram) {
    const RealProgramTimes times =
        timesOf(std::filesystem::path(KERF_SOURCE_DIR) /
                    "tests/golden/fagor/cycle_g68_profile_lines_arc/program.pim",
                "lathe", std::nullopt, "machining_time_golden_lathe");
    EXPECT_NEAR(times.machining, times.programRun, 0.01 * times.programRun);
    EXPECT_GT(times.programRun, 1.0);
}

}  // namespace
}  // namespace kerf::app
