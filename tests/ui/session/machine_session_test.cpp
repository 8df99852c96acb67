#include "ui/session/machine_session.h"

#include <QSignalSpy>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "session_service.h"
#include "simulated_machine.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;
using task::RunState;

// The built-in mill on simulated drives in real time: soft limits X -400..400, Y -300..300,
// Z -500..50 mm (core/machine/presets/mill.toml), tool tip at 0 0 0 at start, no work offset.
class MachineSessionTest : public testing::Test {
protected:
    MachineSessionTest() {
        test::testApp();
        auto mill = machine::loadMachine("mill");
        EXPECT_TRUE(mill.ok());
        config = *mill;
        session =
            std::make_unique<MachineSession>(config, test::connectSimulatedMachine(config), "");
    }

    // Services the session (as its timer does) until `done` or the time is up.
    bool serviceUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 10s) {
        return test::serviceUntil(*session, done, limit);
    }
    bool runToEnd() {
        return serviceUntil([this] {
            const RunState s = session->runState();
            return s == RunState::Finished || s == RunState::Failed || s == RunState::Aborted;
        });
    }
    // The axes stand still after the run: setpoints and drives settle within a few filter
    // lengths (17 ms) and position-loop time constants.
    void settle() {
        serviceUntil([] { return false; }, 150ms);
    }
    double x() const { return session->status().axes[0].nominal; }

    machine::MachineConfig config;
    std::unique_ptr<MachineSession> session;
};

TEST_F(MachineSessionTest, FullSequenceEndsAtTheLastProgrammedPoint) {
    ASSERT_TRUE(
        session->startProgram("0 BEGIN PGM P MM\n"
                              "1 L X+10 Y+5 Z+0 R0 FMAX\n"
                              "2 L X+30 F6000\n"
                              "3 L Y+20\n"
                              "4 END PGM P MM\n",
                              "P.H"));
    ASSERT_TRUE(runToEnd());
    ASSERT_EQ(session->runState(), RunState::Finished) << session->run().diagnostics().size();
    settle();
    const task::MachineStatus& s = session->status();
    // X from block 2, Y from block 3, Z from block 1.
    EXPECT_NEAR(s.axes[0].nominal, 30.0, 1e-6);
    EXPECT_NEAR(s.axes[1].nominal, 20.0, 1e-6);
    EXPECT_NEAR(s.axes[2].nominal, 0.0, 1e-6);
    // The simulated drives follow with a position loop: at rest they come to the setpoint.
    EXPECT_TRUE(serviceUntil(
        [&] {
            return std::abs(s.axes[0].actual - 30.0) < 1e-3 &&
                   std::abs(s.axes[1].actual - 20.0) < 1e-3;
        },
        5s));
    EXPECT_EQ(s.state, task::MachineState::Idle);
}

TEST_F(MachineSessionTest, FeedHoldStopsTheAxesAndResumeReachesTheSameEnd) {
    // 60 mm at 50 mm/s: 1.2 s, time enough to hold in the middle.
    ASSERT_TRUE(session->startProgram(
        "0 BEGIN PGM H MM\n1 L X+60 Y+0 Z+0 R0 F3000\n2 END PGM H MM\n", "H.H"));
    ASSERT_TRUE(serviceUntil([this] { return x() > 10.0; }));
    session->feedHold();
    ASSERT_TRUE(serviceUntil([this] { return session->runState() == RunState::Held; }));
    ASSERT_TRUE(
        serviceUntil([this] { return session->status().state == task::MachineState::Held; }));
    // The interpolator stands; the smoothing filter (17 ms) brings the setpoint after it.
    serviceUntil([] { return false; }, 60ms);
    const double held = x();
    serviceUntil([] { return false; }, 300ms);
    EXPECT_NEAR(x(), held, 1e-9) << "the axes move during feed hold";
    EXPECT_LT(held, 59.0);
    // DIST: what is left of the move to X60.
    EXPECT_NEAR(session->status().axes[0].distanceToGo, 60.0 - held, 1e-9);
    session->cycleStart();
    ASSERT_TRUE(runToEnd());
    EXPECT_EQ(session->runState(), RunState::Finished);
    settle();
    EXPECT_NEAR(x(), 60.0, 1e-6);
}

// Servo time at which X passes `at`, interpolated between two status samples: exact while the
// velocity is constant.
double crossingTime(const std::vector<std::pair<double, double>>& samples, double at) {
    for (size_t i = 1; i < samples.size(); ++i) {
        const auto [t0, x0] = samples[i - 1];
        const auto [t1, x1] = samples[i];
        if (x0 < at && x1 >= at) return t0 + (t1 - t0) * (at - x0) / (x1 - x0);
    }
    return -1.0;
}

TEST_F(MachineSessionTest, HalfFeedOverrideDoublesTheFeedTime) {
    // F2400 = 40 mm/s. Between X5 and X35 the axis runs at constant velocity (it reaches 40 mm/s
    // within ~1 mm at 2000 mm/s^2 and 50000 mm/s^3), so the 30 mm take 0.75 s at 100 % and
    // 1.5 s at 50 %. Measured in servo time (immune to this loaded machine's scheduling) and
    // interpolated between samples: 2 % covers the servo's 1 ms period and rounding.
    const char* program = "0 BEGIN PGM F MM\n1 L X+40 Y+0 Z+0 R0 F2400\n2 END PGM F MM\n";
    auto feedTime = [&](double fraction) {
        session->setFeedOverride(fraction);
        std::vector<std::pair<double, double>> samples;
        EXPECT_TRUE(session->startProgram(program, "F.H"));
        serviceUntil([&] {
            samples.emplace_back(session->status().servoTimeS, x());
            const RunState s = session->runState();
            return s == RunState::Finished || s == RunState::Failed;
        });
        EXPECT_EQ(session->runState(), RunState::Finished);
        return crossingTime(samples, 35.0) - crossingTime(samples, 5.0);
    };
    const double full = feedTime(1.0);
    settle();
    // Back to X0 for the second run.
    ASSERT_TRUE(session->executeMdi("L X+0 FMAX"));
    ASSERT_TRUE(runToEnd());
    settle();
    const double half = feedTime(0.5);
    EXPECT_NEAR(full, 0.75, 0.75 * 0.02);
    EXPECT_NEAR(half, 1.5, 1.5 * 0.02);
}

TEST_F(MachineSessionTest, MdiKeepsSpindleCoolantAndSFromOneBlockToTheNext) {
    // Each MDI block runs as a program of its own; as on a TNC, the S of an MDI TOOL CALL stays
    // for the next block's M3, and the spindle and coolant stay on after each block (a
    // program's END PGM switches them off; an MDI block's end does not).
    auto mdi = [&](const char* block) {
        ASSERT_TRUE(session->executeMdi(block)) << block;
        ASSERT_TRUE(runToEnd()) << block;
        EXPECT_EQ(session->runState(), RunState::Finished) << block;
    };
    mdi("TOOL CALL 1 Z S2000");
    mdi("M3");
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 2000.0);
    mdi("M8");
    mdi("L X+5 FMAX");
    settle();
    EXPECT_NEAR(x(), 5.0, 1e-6);
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 2000.0);
    EXPECT_GT(session->status().actualSpindleRpm, 1000.0);
    EXPECT_TRUE(session->status().coolant);
    // A TOOL CALL with a new S changes the speed of the spindle an earlier block started.
    mdi("TOOL CALL 1 Z S3000");
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 3000.0);
    mdi("M5");
    mdi("M9");
    settle();
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 0.0);
    EXPECT_FALSE(session->status().coolant);
    // M30 as an MDI block switches off what earlier blocks switched on.
    mdi("M13");
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 3000.0);
    EXPECT_TRUE(session->status().coolant);
    mdi("M30");
    settle();
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 0.0);
    EXPECT_FALSE(session->status().coolant);
}

TEST_F(MachineSessionTest, StartAtBlockSkipsTheBlocksBeforeItWithTheStateRestored) {
    // Line 5 is block 4: the scan passes TOOL CALL 3 and blocks 2 and 3 without moving, then
    // approaches the end point of block 3 (X20 Y10 Z0) and runs block 4 to X40.
    const QString program =
        "0 BEGIN PGM S MM\n"
        "1 TOOL CALL 3 Z S1000\n"
        "2 L X+10 Y+0 Z+0 R0 FMAX\n"
        "3 L X+20 Y+10 R0 F3000\n"
        "4 L X+40 R0 F3000\n"
        "5 END PGM S MM\n";
    ASSERT_TRUE(session->startProgram(program, "S.H", 5));
    uint32_t earliestLine = 1000;
    serviceUntil([&] {
        const uint32_t line = session->status().block.line;
        if (line > 0) earliestLine = std::min(earliestLine, line);
        return session->runState() == RunState::Finished || session->runState() == RunState::Failed;
    });
    ASSERT_EQ(session->runState(), RunState::Finished);
    settle();
    EXPECT_EQ(earliestLine, 5u) << "a block before the start block was executed";
    EXPECT_EQ(session->status().toolNumber, 3);
    EXPECT_NEAR(session->status().axes[0].nominal, 40.0, 1e-6);
    EXPECT_NEAR(session->status().axes[1].nominal, 10.0, 1e-6);
}

TEST_F(MachineSessionTest, SoftLimitRefusalNamesTheBlock) {
    QSignalSpy messages(session.get(), &MachineSession::message);
    // X+500 is beyond the soft limit X+400; block 2 is on line 3.
    ASSERT_TRUE(
        session->startProgram("0 BEGIN PGM L MM\n"
                              "1 L X+10 Y+0 Z+0 R0 FMAX\n"
                              "2 L X+500 FMAX\n"
                              "3 END PGM L MM\n",
                              "L.H"));
    ASSERT_TRUE(runToEnd());
    EXPECT_EQ(session->runState(), RunState::Failed);
    bool named = false;
    for (const QList<QVariant>& m : messages) {
        const QString text = m.at(1).toString();
        if (m.at(2).toInt() == 3 && text.contains("Block 2") && text.contains("soft limit"))
            named = true;
    }
    EXPECT_TRUE(named);
    settle();
    EXPECT_LE(x(), 400.0);
}

TEST_F(MachineSessionTest, IncrementalJogMovesOneAxisByTheIncrement) {
    session->setIncrementMm(2.5);
    ASSERT_TRUE(session->jogIncrement(Axis::Y, -1));
    serviceUntil([this] { return session->status().axes[1].nominal < -2.4999; }, 5s);
    settle();
    // The jog generator lands within nanometres of its target.
    EXPECT_NEAR(session->status().axes[1].nominal, -2.5, 1e-5);
    EXPECT_NEAR(x(), 0.0, 1e-9);
    // A program after the jog starts where the jog ended.
    ASSERT_TRUE(session->executeMdi("L X+5 FMAX"));
    ASSERT_TRUE(runToEnd());
    settle();
    EXPECT_NEAR(x(), 5.0, 1e-6);
    EXPECT_NEAR(session->status().axes[1].nominal, -2.5, 1e-5);
}

TEST_F(MachineSessionTest, SingleBlockStopsAtTheEndOfEachBlock) {
    session->setSingleBlock(true);
    ASSERT_TRUE(
        session->startProgram("0 BEGIN PGM B MM\n"
                              "1 L X+5 Y+0 Z+0 R0 F6000\n"
                              "2 L X+10 F6000\n"
                              "3 END PGM B MM\n",
                              "B.H"));
    ASSERT_TRUE(serviceUntil([this] { return session->runState() == RunState::Stopped; }));
    settle();
    EXPECT_NEAR(x(), 5.0, 1e-6);
    session->cycleStart();
    // Block 2 runs, then the machine stops again at its end.
    ASSERT_TRUE(serviceUntil([this] {
        return x() > 10.0 - 1e-6 && session->status().state == task::MachineState::Stopped;
    }));
    settle();
    EXPECT_NEAR(x(), 10.0, 1e-6);
    session->setSingleBlock(false);
    session->cycleStart();
    ASSERT_TRUE(runToEnd());
    EXPECT_EQ(session->runState(), RunState::Finished);
}

// One NC start runs one block completely: `L Z+40 R0 FMAX M5 M9` stops the spindle and the
// coolant before its single-block stop (they went on turning until the next NC start), and the
// status shows what the machine did, S 0 with the spindle at rest.
TEST_F(MachineSessionTest, SingleBlockRunsTheBlocksMFunctionsBeforeItStops) {
    session->setSingleBlock(true);
    ASSERT_TRUE(
        session->startProgram("0 BEGIN PGM E MM\n"
                              "1 TOOL CALL 3 Z S2000\n"
                              "2 L X+0 Y+0 Z+10 R0 FMAX M3 M8\n"
                              "3 L Z+40 R0 FMAX M5 M9\n"
                              "4 L X+10 R0 FMAX\n"
                              "5 END PGM E MM\n",
                              "E.H"));
    const task::MachineStatus& status = session->status();
    auto stoppedAt = [&](double z) {
        return serviceUntil([&] {
            return status.state == task::MachineState::Stopped &&
                   std::fabs(status.axes[2].nominal - z) < 1e-6;
        });
    };
    ASSERT_TRUE(stoppedAt(10.0));
    EXPECT_TRUE(status.coolant);
    EXPECT_EQ(status.programmedSpindleRpm, 2000.0);
    session->cycleStart();
    ASSERT_TRUE(stoppedAt(40.0));
    // M5 waits for the spindle to stand (3000 rpm/s ramp); the stop comes after it.
    EXPECT_LT(std::fabs(status.actualSpindleRpm), 1e-3);
    EXPECT_EQ(status.programmedSpindleRpm, 0.0);
    EXPECT_FALSE(status.coolant);
    EXPECT_EQ(status.block.line, 4u);  // block 3 of the file
    // Still waiting: block 4 has not moved.
    serviceUntil([] { return false; }, 200ms);
    EXPECT_EQ(status.state, task::MachineState::Stopped);
    EXPECT_NEAR(status.axes[0].nominal, 0.0, 1e-6);
    session->cycleStart();
    ASSERT_TRUE(serviceUntil([&] {
        return status.state == task::MachineState::Stopped &&
               std::fabs(status.axes[0].nominal - 10.0) < 1e-6;
    }));
    session->cycleStart();  // END PGM
    ASSERT_TRUE(runToEnd());
    EXPECT_EQ(session->runState(), RunState::Finished);
}

// At a corner the planner blends the end of a block into the next one within the path
// tolerance; single block must stop at the programmed point all the same (it stopped where the
// blend began, Z+9.983 for Z+10), with the setpoints and the drives settled there.
TEST_F(MachineSessionTest, SingleBlockStopsAtTheProgrammedPointOfACorner) {
    session->setSingleBlock(true);
    ASSERT_TRUE(
        session->startProgram("0 BEGIN PGM K MM\n"
                              "1 L X+0 Y+0 Z+10 R0 F3000\n"
                              "2 L X+20 R0 F3000\n"
                              "3 L Y+20 R0 F3000\n"
                              "4 END PGM K MM\n",
                              "K.H"));
    const task::MachineStatus& status = session->status();
    const std::array<std::array<double, 3>, 2> corners = {{{0.0, 0.0, 10.0}, {20.0, 0.0, 10.0}}};
    for (const auto& corner : corners) {
        ASSERT_TRUE(serviceUntil([&] { return status.state == task::MachineState::Stopped; }));
        settle();
        for (size_t a = 0; a < 3; ++a) {
            EXPECT_NEAR(status.axes[a].nominal, corner[a], 1e-6) << "axis " << a;
            EXPECT_NEAR(status.axes[a].actual, corner[a], 1e-3) << "axis " << a;
        }
        session->cycleStart();
        ASSERT_TRUE(serviceUntil([&] { return status.state != task::MachineState::Stopped; }, 2s));
    }
}

// Cycle 200 on the points of cycle 220 (Q216/Q217 centre X50 Y50, Q244 diameter 40, from 0 to
// 270 degrees in 4 points: X70 Y50, X50 Y70, X30 Y50, X50 Y30) and of a PATTERN DEF called with
// M9 (X10 Y10, X30 Y10).
const char* const kPatternProgram =
    "0 BEGIN PGM PAT MM\n"
    "1 TOOL CALL 3 Z S2000\n"
    "2 L X+0 Y+0 Z+30 R0 FMAX M3 M8\n"
    "3 CYCL DEF 200 DRILLING\n"
    "  Q200=2 Q201=-3 Q206=300 Q202=3 Q210=0\n"
    "  Q203=+0 Q204=20 Q211=0 Q395=0\n"
    "4 CYCL DEF 220 POLAR PATTERN\n"
    "  Q216=+50 Q217=+50 Q244=40 Q245=+0 Q246=+270\n"
    "  Q247=+0 Q241=4 Q200=2 Q203=+0 Q204=20 Q301=1 Q365=0\n"
    "5 PATTERN DEF\n"
    "  POS1 (X+10 Y+10 Z+0)\n"
    "  POS2 (X+30 Y+10 Z+0)\n"
    "6 CYCL CALL PAT M9\n"
    "7 L Z+30 R0 FMAX\n"
    "8 END PGM PAT MM\n";

// Single block stops between the points of a pattern (TNC 320 cycle manuals, cycles 220 and 221:
// the control stops between the points; [choice] CYCL CALL PAT the same way): one NC start
// machines one point, and the calling block's M functions run after its last point, before the
// stop (docs/hmi.md, "Program run").
TEST_F(MachineSessionTest, SingleBlockStopsBetweenThePointsOfAPattern) {
    session->setSingleBlock(true);
    ASSERT_TRUE(session->startProgram(kPatternProgram, "PAT.H"));
    const task::MachineStatus& status = session->status();
    struct Stop {
        double x, y, z;
        bool coolant;
    };
    std::vector<Stop> stops;
    for (int start = 0; start < 12; ++start) {
        ASSERT_TRUE(serviceUntil([&] {
            return status.state == task::MachineState::Stopped ||
                   session->runState() == RunState::Finished;
        }));
        if (session->runState() == RunState::Finished) break;
        settle();
        stops.push_back({status.axes[0].nominal, status.axes[1].nominal, status.axes[2].nominal,
                         status.coolant});
        session->cycleStart();
        ASSERT_TRUE(serviceUntil([&] { return status.state != task::MachineState::Stopped; }));
    }
    ASSERT_EQ(session->runState(), RunState::Finished);
    // Block 2, four points of 220, two of the pattern, block 7; END PGM takes the last start.
    const std::vector<std::array<double, 2>> expected = {{0, 0},   {70, 50}, {50, 70}, {30, 50},
                                                         {50, 30}, {10, 10}, {30, 10}, {30, 10}};
    ASSERT_EQ(stops.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(stops[i].x, expected[i][0], 1e-6) << "stop " << i;
        EXPECT_NEAR(stops[i].y, expected[i][1], 1e-6) << "stop " << i;
        // Blocks 2 and 7 at Z+30; at a point the cycle ended at the 2nd set-up clearance.
        const bool block = i == 0 || i + 1 == expected.size();
        EXPECT_NEAR(stops[i].z, block ? 30.0 : 20.0, 1e-6) << "stop " << i;
    }
    // M9 of CYCL CALL PAT: on until the last point, off at the stop after it.
    for (size_t i = 0; i < 6; ++i)
        EXPECT_TRUE(stops[i].coolant) << "stop " << i;
    EXPECT_FALSE(stops[6].coolant);
}

TEST_F(MachineSessionTest, FullSequenceRunsAPatternWithoutAStop) {
    session->setSingleBlock(false);
    ASSERT_TRUE(session->startProgram(kPatternProgram, "PAT.H"));
    bool stopped = false;
    ASSERT_TRUE(serviceUntil(
        [&] {
            stopped = stopped || session->status().state == task::MachineState::Stopped;
            return session->runState() == RunState::Finished ||
                   session->runState() == RunState::Failed;
        },
        60s));  // six holes in real time: about as long as the single-block run
    EXPECT_EQ(session->runState(), RunState::Finished);
    EXPECT_FALSE(stopped);
    settle();
    EXPECT_NEAR(session->status().axes[0].nominal, 30.0, 1e-6);
    EXPECT_NEAR(session->status().axes[1].nominal, 10.0, 1e-6);
    EXPECT_NEAR(session->status().axes[2].nominal, 30.0, 1e-6);
    EXPECT_FALSE(session->status().coolant);
}

TEST_F(MachineSessionTest, ContinuousJogRunsUntilStopped) {
    ASSERT_TRUE(session->jog(Axis::X, 1));
    ASSERT_TRUE(serviceUntil([this] { return x() > 5.0; }, 5s));
    session->jogStop(Axis::X);
    ASSERT_TRUE(
        serviceUntil([this] { return session->status().state == task::MachineState::Idle; }));
    settle();
    const double stopped = x();
    settle();
    EXPECT_GT(stopped, 5.0);
    EXPECT_DOUBLE_EQ(x(), stopped);
}

TEST_F(MachineSessionTest, ManualSpindleRunsAtTheRequestedSpeed) {
    ASSERT_TRUE(session->spindle(true, 1200.0));
    // 1200 rpm at 3000 rpm/s: 0.4 s and the jerk ramps.
    EXPECT_TRUE(serviceUntil(
        [this] { return std::abs(session->status().actualSpindleRpm - 1200.0) < 1.0; }, 5s));
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 1200.0);
    ASSERT_TRUE(
        serviceUntil([this] { return session->status().state == task::MachineState::Idle; }));
    ASSERT_TRUE(session->spindle(false));
    EXPECT_TRUE(serviceUntil([this] { return session->status().actualSpindleRpm == 0.0; }, 5s));
}

TEST(MachineSessionLathe, RunsAFagorProgramWithXInDiameter) {
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    MachineSession session(*lathe, test::connectSimulatedMachine(*lathe), "");
    // X is programmed as a diameter: X40 then X60 are radii 20 and 30 in the machine.
    ASSERT_TRUE(
        session.startProgram("N1 G90 G00 X40 Z10\nN2 G01 X60 F3000\nN3 M30\n", "LATHE.PIT"));
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (session.runState() == RunState::Running && std::chrono::steady_clock::now() < deadline) {
        session.service();
        std::this_thread::sleep_for(2ms);
    }
    ASSERT_EQ(session.runState(), RunState::Finished);
    std::this_thread::sleep_for(100ms);
    session.service();
    EXPECT_NEAR(session.status().axes[0].nominal, 30.0, 1e-6);
    EXPECT_NEAR(session.status().axes[2].nominal, 10.0, 1e-6);
}

// Single block on a FAGOR canned cycle (seed 002 has single block stop at the end of each block
// and a canned cycle is one block; docs/fagor.md): the G81's three passes run without a stop
// and the machine stops back at the call point, then after the next block.
TEST(MachineSessionLathe, SingleBlockRunsAFagorCannedCycleAsOneBlock) {
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    MachineSession session(*lathe, test::connectSimulatedMachine(*lathe), "");
    session.setSingleBlock(true);
    // Call point X40 Z5 (radius 20); A X30 Z0, B X30 Z-10: 5 mm in ceil(5 / 2) = 3 passes down
    // to radius 15 along Z0 .. Z-10, the cycle ending at the call point.
    ASSERT_TRUE(
        session.startProgram("N1 G90 G94 G00 X40 Z5 F3000\n"
                             "N2 G81 X30 Z0 Q30 R-10 C2\n"
                             "N3 G00 X60 Z20\n"
                             "N4 M30\n",
                             "SBLK.PIM"));
    struct Stop {
        double x, z, lowestX, lowestZ;
    };
    std::vector<Stop> stops;
    double lowestX = 1e9;
    double lowestZ = 1e9;
    bool wasStopped = false;
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while ((session.runState() == RunState::Running || session.runState() == RunState::Stopped) &&
           std::chrono::steady_clock::now() < deadline) {
        session.service();
        const double x = session.status().axes[0].nominal;
        const double z = session.status().axes[2].nominal;
        lowestX = std::min(lowestX, x);
        lowestZ = std::min(lowestZ, z);
        const bool stopped = session.runState() == RunState::Stopped;
        if (stopped && !wasStopped) {
            stops.push_back({x, z, lowestX, lowestZ});
            lowestX = lowestZ = 1e9;
            session.cycleStart();
        }
        wasStopped = stopped;
        std::this_thread::sleep_for(2ms);
    }
    ASSERT_EQ(session.runState(), RunState::Finished);
    ASSERT_EQ(stops.size(), 3u) << "single block stopped inside the canned cycle";
    // The setpoints lag the path by the setpoint filter: within 0.5 mm.
    EXPECT_NEAR(stops[0].x, 20.0, 0.5);
    EXPECT_NEAR(stops[0].z, 5.0, 0.5);
    EXPECT_NEAR(stops[1].x, 20.0, 0.5);  // back at the call point
    EXPECT_NEAR(stops[1].z, 5.0, 0.5);
    EXPECT_NEAR(stops[1].lowestX, 15.0, 0.01);  // every pass ran before the stop
    EXPECT_NEAR(stops[1].lowestZ, -10.0, 0.01);
    EXPECT_NEAR(stops[2].x, 30.0, 0.5);
    EXPECT_NEAR(stops[2].z, 20.0, 0.5);
}

// The FAGOR 8035 stops after every block in single block: M8 alone, the G4 dwell and T2 D2 get
// their own stops, where the axes stand. A parameter assignment gives the machine nothing: it
// runs with the next block (docs/hmi.md).
TEST(MachineSessionLathe, MdiKeepsTheSpindleSpeedFromOneBlockToTheNext) {
    // S1000 as one MDI block, M3 as the next: the spindle turns at 1000 rpm (it ran at S0).
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    MachineSession session(*lathe, test::connectSimulatedMachine(*lathe), "");
    for (const char* block : {"G97 S1000", "M3"}) {
        ASSERT_TRUE(session.executeMdi(block)) << block;
        ASSERT_TRUE(test::serviceUntil(
            session,
            [&] {
                return session.runState() == RunState::Finished ||
                       session.runState() == RunState::Failed;
            },
            10s));
        EXPECT_EQ(session.runState(), RunState::Finished) << block;
    }
    EXPECT_DOUBLE_EQ(session.status().programmedSpindleRpm, 1000.0);
}

TEST(MachineSessionLathe, SingleBlockStopsAfterAFagorBlockWithoutAMove) {
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    MachineSession session(*lathe, test::connectSimulatedMachine(*lathe), "");
    session.setSingleBlock(true);
    ASSERT_TRUE(
        session.startProgram("N1 G90 G94 G00 X40 Z5 F3000\n"
                             "N2 M8\n"
                             "N3 (P1 = 5)\n"
                             "N4 G04 K10\n"
                             "N5 G01 X30\n"
                             "N6 T2 D2\n"
                             "N7 M30\n",
                             "SBLKM.PIM"));
    struct Stop {
        uint32_t line;
        double x;
        bool coolant;
    };
    std::vector<Stop> stops;
    uint32_t stoppedAt = 0;  // the block of the stop NC start was pressed at
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while ((session.runState() == RunState::Running || session.runState() == RunState::Stopped) &&
           std::chrono::steady_clock::now() < deadline) {
        session.service();
        // A block without a move runs and stops within a servo cycle or two: between two looks
        // here the state may stay Stopped, at the next block.
        const uint32_t line = session.status().block.line;
        if (session.runState() == RunState::Stopped && line != stoppedAt) {
            stops.push_back({line, session.status().axes[0].nominal, session.status().coolant});
            stoppedAt = line;
            session.cycleStart();
        }
        std::this_thread::sleep_for(2ms);
    }
    ASSERT_EQ(session.runState(), RunState::Finished);
    const std::vector<uint32_t> lines = {1, 2, 4, 5, 6};
    ASSERT_EQ(stops.size(), lines.size());
    for (size_t i = 0; i < lines.size(); ++i)
        EXPECT_EQ(stops[i].line, lines[i]) << "stop " << i;
    EXPECT_FALSE(stops[0].coolant);  // M8 waits for the next NC start
    EXPECT_TRUE(stops[1].coolant);
    EXPECT_NEAR(stops[1].x, 20.0, 0.5);  // M8 and G4 stop where N1 left the axes (radius 20)
    EXPECT_NEAR(stops[2].x, 20.0, 0.5);
    EXPECT_NEAR(stops[3].x, 15.0, 0.5);
    EXPECT_NEAR(stops[4].x, 15.0, 0.5);
}

// G95: F is mm per revolution; the feed shown while a block runs is the path feed it gives at
// the programmed speed, 0.2 mm x 1000 rpm = 200 mm/min (it used to show 0.2 as mm/min).
TEST(MachineSessionLathe, AFeedPerRevolutionShowsAsThePathFeedAtTheProgrammedSpeed) {
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    MachineSession session(*lathe, test::connectSimulatedMachine(*lathe), "");
    ASSERT_TRUE(session.startProgram(
        "N1 G90 G00 X40 Z10\nN2 G95 S1000 M3\nN3 G01 Z-20 F0.2\nN4 M30\n", "FEED.PIT"));
    double shown = 0.0;
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (session.runState() == RunState::Running && std::chrono::steady_clock::now() < deadline) {
        session.service();
        if (session.status().block.line == 3) shown = session.status().programmedFeedMmPerMin;
        if (shown > 0.0) break;
        std::this_thread::sleep_for(2ms);
    }
    EXPECT_NEAR(shown, 200.0, 1e-9);
    session.stop();
}

// A thread's lead shows as its path feed too: G33 with the lead 1.5 at 800 rpm is 1200 mm/min
// (1.5 mm/rev under G95; it showed F 0 while the thread was cut).
TEST(MachineSessionLathe, AThreadShowsItsLeadAsThePathFeed) {
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    MachineSession session(*lathe, test::connectSimulatedMachine(*lathe), "");
    ASSERT_TRUE(session.startProgram(
        "N1 G90 G00 X30 Z5\nN2 G95 S800 M3\nN3 G33 Z-30 L1.5\nN4 M30\n", "THREAD.PIT"));
    double shown = 0.0;
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (session.runState() == RunState::Running && std::chrono::steady_clock::now() < deadline) {
        session.service();
        if (session.status().block.line == 3) shown = session.status().programmedFeedMmPerMin;
        if (shown > 0.0) break;
        std::this_thread::sleep_for(2ms);
    }
    EXPECT_NEAR(shown, 1200.0, 1e-9);
    session.stop();
}

}  // namespace
}  // namespace kerf::ui
