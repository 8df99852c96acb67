#include "ui/testrun/test_run_controller.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "graphics/stock/progressive_stock.h"
#include "motion/sim/simulated_clock.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "tests/support/machining_time_programs.h"

namespace kerf::ui {
namespace {

// Two holes with a 5 mm drill (T-ANGLE 118) 10 mm deep, then a slot with a flat 10 mm end mill,
// 2 mm deep from X+60 to X+90 at Y+40. Line n of the file is block n - 1.
const char* kParts =
    "0 BEGIN PGM PARTS MM\n"
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
    "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
    "3 TOOL CALL 1 Z S2000\n"
    "4 L Z+5 R0 FMAX\n"
    "5 L X+15 Y+20 R0 FMAX\n"
    "6 L Z-10 R0 F100\n"
    "7 L Z+5 R0 FMAX\n"
    "8 L X+30 Y+20 R0 FMAX\n"
    "9 L Z-10 R0 F100\n"
    "10 L Z+5 R0 FMAX\n"
    "11 TOOL CALL 2 Z S3000\n"
    "12 L X+60 Y+40 R0 FMAX\n"
    "13 L Z-2 R0 F200\n"
    "14 L X+90 F300\n"
    "15 L Z+5 R0 FMAX\n"
    "16 END PGM PARTS MM\n";

struct Fixture {
    explicit Fixture(const char* machineName = "mill")
        : machine(*machine::loadMachine(machineName)) {
        test::testApp();
        std::filesystem::copy_file(
            std::filesystem::path(KERF_SOURCE_DIR) / "tests/graphics/programs/TOOL.T",
            root / "TOOL.T");
        controller.setTickMs(0);  // the tests drive the playback with advance()
        controller.setMachiningClock(motion::makeSimulatedClock);
    }
    std::filesystem::path root = kerf::test::uniqueTempDir("testrun");
    machine::MachineConfig machine;
    TestRunController controller{machine, root};
    // Starts the program and waits until it is interpreted.
    void start(const char* text, program::Dialect dialect = program::Dialect::Klartext,
               const char* name = "PARTS.H") {
        QSignalSpy ready(&controller, &TestRunController::programReady);
        controller.start(QString::fromUtf8(text), root / name, dialect);
        ASSERT_TRUE(ready.wait(20000));
    }
};

// Feeds alone: 15 mm at 100 mm/min twice, 7 mm at 200 and 30 mm at 300 mm/min.
constexpr double kPartsFeedS = 9.0 + 9.0 + 2.1 + 6.0;

TEST(TestRun, FinishesWithTheMachiningTimeAndRemovedVolumeOfTheProgram) {
    Fixture f;
    f.controller.setSpeed(TestRunSpeed::Max);
    f.start(kParts);
    // The time of the program run on the machine (simulated), not length / feed: within 1 %.
    const double programRunS = kerf::test::simulatedProgramRunS(f.root / "PARTS.H", kParts, "mill");
    EXPECT_NEAR(f.controller.machiningTimeS(), programRunS, 0.01 * programRunS);
    EXPECT_GT(f.controller.machiningTimeS(), kPartsFeedS);
    EXPECT_EQ(f.controller.state(), TestRunController::State::Finished);
    EXPECT_DOUBLE_EQ(f.controller.playbackTimeS(), f.controller.machiningTimeS());

    ASSERT_NE(f.controller.stock(), nullptr);
    ASSERT_TRUE(f.controller.stock()->waitFinished(std::chrono::seconds(30)));
    // A drilled hole: a cylinder of R 2.5 down to the point, whose cone (118 degrees) is
    // h = R / tan(59 deg) long. The slot: 30 x 10 x 2 and the two half circles at its ends.
    const double pi = std::numbers::pi;
    const double cone = 2.5 / std::tan(59.0 * pi / 180.0);
    const double hole = pi * 2.5 * 2.5 * (10.0 - cone) + pi * 2.5 * 2.5 * cone / 3.0;
    const double slot = 30.0 * 10.0 * 2.0 + pi * 5.0 * 5.0 * 2.0;
    const double expected = 2.0 * hole + slot;
    EXPECT_NEAR(f.controller.stock()->latest()->removedVolumeMm3, expected, 0.02 * expected);
}

TEST(TestRun, SpeedSetsHowFastMachiningTimePassesAndTheToolFollowsThePath) {
    Fixture f;
    f.controller.setSpeed(TestRunSpeed::Times10);
    f.start(kParts);
    ASSERT_EQ(f.controller.state(), TestRunController::State::Playing);
    f.controller.advance(0.5);  // x10: five seconds of machining
    EXPECT_NEAR(f.controller.playbackTimeS(), 5.0, 1e-9);
    // Five seconds in, the drill is on its way down the first hole (15, 20) at 100 mm/min since
    // the end of the command before its move (line 7).
    const TestRunProgram& program = *f.controller.program();
    size_t drill = 0;
    while (drill < program.commands.size() && program.commands[drill].location.line != 7)
        ++drill;
    ASSERT_GT(drill, 0u);
    ASSERT_LT(drill, program.commands.size());
    const double drilling = 5.0 - program.endTimeS[drill - 1];
    const Vec3 tool = f.controller.toolPosition();
    EXPECT_NEAR(tool.x(), 15.0, 1e-4);
    EXPECT_NEAR(tool.y(), 20.0, 1e-4);
    // The playback interpolates a command linearly in its time, which includes the stop at the
    // bottom (9.009 s for 15 mm at 100 mm/min): 0.007 mm off the feed's position.
    EXPECT_NEAR(tool.z(), 5.0 - 100.0 / 60.0 * drilling, 1e-2);
    EXPECT_EQ(f.controller.currentLine(), 7);
    // The status tabs get the interpreter's state at that block: line 7, tool 1.
    const auto* status = f.controller.program()->statusAt(5.0);
    ASSERT_NE(status, nullptr);
    EXPECT_EQ(status->status.line, 7u);
    EXPECT_EQ(status->status.tool.number, 1);
    std::vector<uint32_t> statusLines;
    QObject::connect(
        &f.controller, &TestRunController::programStatusChanged,
        [&statusLines](const interp::ProgramStatus& s) { statusLines.push_back(s.line); });

    f.controller.setSpeed(TestRunSpeed::Times100);
    f.controller.advance(0.1);  // x100: ten more seconds
    EXPECT_NEAR(f.controller.playbackTimeS(), 15.0, 1e-9);
    // Fifteen seconds in: the second hole (line 10) is being drilled.
    EXPECT_EQ(statusLines, std::vector<uint32_t>{10u});
    f.controller.stop();
    f.controller.advance(1.0);  // stopped: time stands still
    EXPECT_NEAR(f.controller.playbackTimeS(), 15.0, 1e-9);
    EXPECT_EQ(f.controller.state(), TestRunController::State::Stopped);

    f.controller.reset();
    EXPECT_EQ(f.controller.playbackTimeS(), 0.0);
    EXPECT_EQ(f.controller.state(), TestRunController::State::Ready);

    // With the timer, real time passes: a few ticks at x1 move the playback on by as much as
    // the clock, never more (measured, not assumed: a loaded host stretches the 300 ms wait).
    f.controller.setTickMs(20);
    f.controller.setSpeed(TestRunSpeed::Real);
    QElapsedTimer clock;
    clock.start();
    f.controller.play();
    QTest::qWait(300);
    const double elapsedS = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
    EXPECT_GT(f.controller.playbackTimeS(), 0.1);
    EXPECT_LE(f.controller.playbackTimeS(), elapsedS);
    f.controller.setSpeed(TestRunSpeed::Max);
    EXPECT_EQ(f.controller.state(), TestRunController::State::Finished);
}

TEST(TestRun, MachiningTimeIsThatOfTheSimulatedProgramRunOnBothMachines) {
    // Before, the test run took length / feed: 26.70 s against the mill program's 27.80 s run,
    // 59.44 s against the lathe program's 47.29 s (G96 at the speed of each move's start).
    Fixture mill;
    mill.start(kerf::test::kMillTimingProgram, program::Dialect::Klartext, "TIMING.H");
    const double millRunS = kerf::test::simulatedProgramRunS(
        mill.root / "TIMING.H", kerf::test::kMillTimingProgram, "mill");
    EXPECT_NEAR(mill.controller.machiningTimeS(), millRunS, 0.01 * millRunS);
    EXPECT_GT(mill.controller.machiningTimeS(), kerf::test::kMillFeedAndDwellS);

    Fixture lathe("lathe");
    lathe.start(kerf::test::kLatheTimingProgram, program::Dialect::Fagor, "TIMING.PIT");
    const double latheRunS = kerf::test::simulatedProgramRunS(
        lathe.root / "TIMING.PIT", kerf::test::kLatheTimingProgram, "lathe");
    EXPECT_NEAR(lathe.controller.machiningTimeS(), latheRunS, 0.01 * latheRunS);
}

TEST(TestRun, AProgramWithAnErrorStopsWithADiagnosticAtItsLine) {
    Fixture f;
    QSignalSpy diagnostics(&f.controller, &TestRunController::diagnostic);
    f.start(
        "0 BEGIN PGM BAD MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
        "3 TOOL CALL 1 Z S2000\n4 L Z+5 R0 FMAX\n5 BOGUS WORD\n6 END PGM BAD MM\n");
    EXPECT_EQ(f.controller.state(), TestRunController::State::Failed);
    bool errorAtLine6 = false;
    for (const QList<QVariant>& d : diagnostics) {
        if (d.at(0).value<Severity>() == Severity::Error && d.at(2).toInt() == 6)
            errorAtLine6 = true;
    }
    EXPECT_TRUE(errorAtLine6) << diagnostics.count() << " diagnostics";
    // Nothing plays.
    f.controller.play();
    EXPECT_EQ(f.controller.state(), TestRunController::State::Failed);
}

TEST(TestRun, ADinIsoProgramRunsOnTheSameEngine) {
    Fixture f;
    f.controller.setSpeed(TestRunSpeed::Max);
    f.start(
        "%PARTS G71 *\nN10 G00 G40 G90 X+10 Y+0 Z+5 *\nN20 G01 Z-1 F100 *\n"
        "N30 X+40 *\nN99999999 %PARTS G71 *\n",
        program::Dialect::TncIso, "PARTS.I");
    EXPECT_EQ(f.controller.state(), TestRunController::State::Finished);
    // 6 mm down and 30 mm along X at 100 mm/min.
    EXPECT_GT(f.controller.machiningTimeS(), 36.0 * 60.0 / 100.0);
    const TestRunProgram& program = *f.controller.program();
    ASSERT_FALSE(program.commands.empty());
    EXPECT_EQ(program.commands.front().location.line, 2u);
}

}  // namespace
}  // namespace kerf::ui
