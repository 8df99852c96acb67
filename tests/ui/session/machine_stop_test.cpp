// Stop (the TNC's internal stop) through the session: from every state the machine can be in,
// it returns to ready within a bounded time, with the spindle and the coolant off.
#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "session_service.h"
#include "simulated_machine.h"
#include "ui/session/machine_session.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;
using task::MachineState;
using task::RunState;

// The built-in mill on simulated drives in real time, the tool tip at 0 0 0 at start.
class MachineStopTest : public testing::Test {
public:
    MachineStopTest() {
        test::testApp();
        config = *machine::loadMachine("mill");
        session =
            std::make_unique<MachineSession>(config, test::connectSimulatedMachine(config), "");
    }
    bool serviceUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 10s) {
        return test::serviceUntil(*session, done, limit);
    }
    double nominal(Axis a) const {
        return session->status().axes[static_cast<size_t>(axisIndex(a))].nominal;
    }
    const task::MachineStatus& status() const { return session->status(); }
    // Ready: the axes stand (Idle), nothing runs or waits, a new command is taken.
    bool ready() const { return status().state == MachineState::Idle && !session->busy(); }
    // Stop, then ready within `limit` (braking from the feeds used here takes milliseconds; the
    // bound leaves room for a loaded machine).
    ::testing::AssertionResult stopsToReady(std::chrono::milliseconds limit = 2s) {
        session->stop();
        if (!serviceUntil([this] { return ready(); }, limit)) {
            return ::testing::AssertionFailure()
                   << "still " << task::machineStateName(status().state) << ", run "
                   << task::runStateName(session->runState()) << " after the stop";
        }
        return ::testing::AssertionSuccess();
    }
    // The spindle (3000 rpm/s ramp) comes to rest and the coolant is off.
    ::testing::AssertionResult spindleAndCoolantOff() {
        if (!serviceUntil([this] { return status().actualSpindleRpm == 0.0; }, 3s))
            return ::testing::AssertionFailure()
                   << "the spindle still turns at " << status().actualSpindleRpm << " rpm";
        if (status().coolant) return ::testing::AssertionFailure() << "the coolant is on";
        return ::testing::AssertionSuccess();
    }

    machine::MachineConfig config;
    std::unique_ptr<MachineSession> session;
};

// M3 M8 at 1000 rpm, then two blocks along X.
const QString kTwoBlocks =
    "0 BEGIN PGM T MM\n"
    "1 TOOL CALL 3 Z S1000\n"
    "2 L X+5 Y+0 Z+0 R0 F6000 M3 M8\n"
    "3 L X+10 R0 F6000\n"
    "4 END PGM T MM\n";

TEST_F(MachineStopTest, StopAtASingleBlockStopReturnsToReady) {
    session->setSingleBlock(true);
    ASSERT_TRUE(session->startProgram(kTwoBlocks, "T.H"));
    ASSERT_TRUE(serviceUntil([this] { return session->runState() == RunState::Stopped; }));
    ASSERT_TRUE(serviceUntil([this] { return status().state == MachineState::Stopped; }));
    // The setpoint filter (17 ms) and the spindle ramp (3000 rpm/s) come to rest while it waits.
    ASSERT_TRUE(serviceUntil([this] {
        return std::fabs(nominal(Axis::X) - 5.0) < 1e-6 &&
               std::fabs(status().actualSpindleRpm - 1000.0) < 1e-6;
    }));
    EXPECT_TRUE(status().coolant);
    ASSERT_TRUE(stopsToReady());
    EXPECT_EQ(session->runState(), RunState::Aborted);
    EXPECT_TRUE(spindleAndCoolantOff());
    EXPECT_EQ(status().programmedSpindleRpm, 0.0);
    // The second block never ran; the machine takes manual and MDI commands again.
    EXPECT_NEAR(nominal(Axis::X), 5.0, 1e-6);
    ASSERT_TRUE(session->jogIncrement(Axis::Y, 1));
    ASSERT_TRUE(serviceUntil([this] { return ready() && nominal(Axis::Y) > 1.0 - 1e-6; }));
    EXPECT_TRUE(session->executeMdi("L X+0 R0 FMAX"));
}

TEST_F(MachineStopTest, StopInsideACycleReturnsToReady) {
    // Cycle 200 from Z+10: surface 0, depth 3 in one infeed, 2 s dwell at the bottom (Q211).
    ASSERT_TRUE(
        session->startProgram("0 BEGIN PGM C MM\n"
                              "1 TOOL CALL 3 Z S1000\n"
                              "2 L X+10 Y+0 Z+10 R0 FMAX M3 M8\n"
                              "3 CYCL DEF 200 DRILLING\n"
                              "  Q200=2\n  Q201=-3\n  Q206=600\n  Q202=5\n  Q210=0\n"
                              "  Q203=+0\n  Q204=10\n  Q211=2\n  Q395=0\n"
                              "4 CYCL CALL\n"
                              "5 END PGM C MM\n",
                              "C.H"))
        << "refused";
    // At the bottom of the hole, in the dwell.
    ASSERT_TRUE(serviceUntil([this] { return nominal(Axis::Z) < -3.0 + 1e-6; }));
    serviceUntil([] { return false; }, 200ms);
    ASSERT_EQ(session->runState(), RunState::Running);
    ASSERT_TRUE(stopsToReady(500ms));  // well inside the 2 s dwell
    EXPECT_NEAR(nominal(Axis::Z), -3.0, 1e-6) << "the cycle went on after the stop";
    EXPECT_TRUE(spindleAndCoolantOff());
}

struct DwellProgram {
    const char* machine;
    const char* file;
    QString text;
    bool singleBlock = false;
};

// A 3 s dwell after a move to X5 (lathe: a diameter of 10) with the spindle and the coolant on,
// in each dialect, and cycle 200's Q211 in single block (the whole cycle is one step).
std::vector<DwellProgram> dwellPrograms() {
    const QString cycle200 =
        "0 BEGIN PGM Q MM\n"
        "1 TOOL CALL 3 Z S1000\n"
        "2 L X+5 Y+0 Z+10 R0 FMAX M3 M8\n"
        "3 CYCL DEF 200 DRILLING\n"
        "  Q200=2\n  Q201=-3\n  Q206=600\n  Q202=5\n  Q210=0\n"
        "  Q203=+0\n  Q204=10\n  Q211=3\n  Q395=0\n"
        "4 CYCL CALL\n"
        "5 END PGM Q MM\n";
    return {
        {"mill", "D.H",
         "0 BEGIN PGM D MM\n1 TOOL CALL 3 Z S1000\n2 L X+5 Y+0 Z+0 R0 F6000 M3 M8\n"
         "3 CYCL DEF 9.0 DWELL TIME\n4 CYCL DEF 9.1 DWELL 3\n5 L X+10 R0 F6000\n"
         "6 END PGM D MM\n"},
        {"mill", "D.I",
         "%D G71 *\nN10 T3 G17 S1000 *\nN20 G01 G90 X+5 Y+0 Z+0 F6000 M3 M8 *\n"
         "N30 G04 F3 *\nN40 G01 X+10 *\nN99999999 %D G71 *\n"},
        {"lathe", "D.PIT",
         "N10 G90 G01 X10 Z0 F3000\nN20 S1000 M3 M8\nN30 G04 K300\n"
         "N40 G01 X20\nN50 M30\n"},
        {"mill", "Q.H", cycle200, true},
    };
}

// Stop in a dwell ends the program at once, in every dialect and in single block: ready, not
// "stopping" until the dwell has run out, nor for ever. An attempt to set a preset meanwhile is
// refused (a program runs) and changes nothing.
TEST_F(MachineStopTest, StopInADwellReturnsToReady) {
    for (const DwellProgram& p : dwellPrograms()) {
        SCOPED_TRACE(p.file);
        config = *machine::loadMachine(p.machine);
        session =
            std::make_unique<MachineSession>(config, test::connectSimulatedMachine(config), "");
        session->setSingleBlock(p.singleBlock);
        ASSERT_TRUE(session->startProgram(p.text, p.file)) << "refused";
        // In the dwell: at X5 (cycle 200: at the bottom of the hole), the spindle at speed.
        ASSERT_TRUE(serviceUntil([this, &p] {
            // Single block: NC start at the stop after the positioning block.
            if (status().state == MachineState::Stopped) session->cycleStart();
            const bool inHole = p.file != std::string("Q.H") || nominal(Axis::Z) < -3.0 + 1e-6;
            return std::fabs(nominal(Axis::X) - 5.0) < 1e-6 && inHole &&
                   std::fabs(status().actualSpindleRpm - 1000.0) < 1e-6;
        }));
        serviceUntil([] { return false; }, 200ms);
        ASSERT_EQ(session->runState(), RunState::Running);
        const double origin = status().axes[0].nominal;
        EXPECT_FALSE(session->setPresetByEntry(Axis::X, 0.0));
        EXPECT_EQ(status().axes[0].nominal, origin);
        ASSERT_EQ(session->runState(), RunState::Running);
        ASSERT_TRUE(stopsToReady(500ms));  // well inside the 3 s dwell
        EXPECT_EQ(session->runState(), RunState::Aborted);
        EXPECT_NEAR(nominal(Axis::X), 5.0, 1e-6) << "the program went on after the stop";
        EXPECT_TRUE(spindleAndCoolantOff());
        session->setSingleBlock(false);
        EXPECT_TRUE(
            session->executeMdi(p.machine == std::string("lathe") ? "G00 X10" : "L X+0 FMAX"));
        ASSERT_TRUE(serviceUntil([this] { return ready(); }));
    }
}

TEST_F(MachineStopTest, StopWithoutAProgramTurnsSpindleAndCoolantOff) {
    ASSERT_TRUE(session->spindle(true, 1200.0));
    ASSERT_TRUE(serviceUntil([this] { return status().actualSpindleRpm > 1199.0 && ready(); }));
    ASSERT_TRUE(session->coolant(true));
    ASSERT_TRUE(serviceUntil([this] { return status().coolant && ready(); }));
    ASSERT_TRUE(stopsToReady());
    EXPECT_TRUE(spindleAndCoolantOff());
    EXPECT_EQ(status().programmedSpindleRpm, 0.0);
}

struct ReachableState {
    std::string state;
    std::function<bool()> reach;  // true once the machine is in the state
};

// Every state the session can reach, each from ready.
std::vector<ReachableState> reachableStates(MachineStopTest& t) {
    MachineSession* session = t.session.get();
    const QString longMove = "0 BEGIN PGM L MM\n1 L X+40 Y+0 Z+0 R0 F1200 M3\n2 END PGM L MM\n";
    const auto atX = [&t](double x) {
        return t.serviceUntil([&t, x] { return std::fabs(t.nominal(Axis::X) - x) > 0.5; });
    };
    return {
        {"idle", [] { return true; }},
        {"running",
         [=, &t] {
             return session->startProgram(longMove, "L.H") && atX(t.nominal(Axis::X)) &&
                    t.status().state == MachineState::Running;
         }},
        {"feed hold",
         [=, &t] {
             if (!session->startProgram(longMove, "L.H") || !atX(t.nominal(Axis::X))) return false;
             session->feedHold();
             return t.serviceUntil([=, &t] { return t.status().state == MachineState::Held; });
         }},
        {"single-block stop",
         [=, &t] {
             session->setSingleBlock(true);
             const bool started = session->startProgram(kTwoBlocks, "T.H");
             const bool stopped = started && t.serviceUntil([=, &t] {
                 return t.status().state == MachineState::Stopped;
             });
             session->setSingleBlock(false);
             return stopped;
         }},
        {"program stop M0",
         [=, &t] {
             return session->startProgram(
                        "0 BEGIN PGM M MM\n1 L X+2 Y+0 Z+0 R0 F6000 M3\n2 STOP\n"
                        "3 L X+4\n4 END PGM M MM\n",
                        "M.H") &&
                    t.serviceUntil([=, &t] { return session->runState() == RunState::Stopped; });
         }},
        {"MDI",
         [=, &t] {
             return session->executeMdi("L X+30 R0 F1200") && atX(t.nominal(Axis::X)) &&
                    t.status().state == MachineState::Running;
         }},
        {"start at block",
         [=, &t] {
             return session->startProgram(
                        "0 BEGIN PGM S MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n"
                        "2 L X+5 R0 F1200 M3\n3 L X+30 R0 F1200\n"
                        "4 END PGM S MM\n",
                        "S.H", 4) &&
                    t.serviceUntil([=, &t] { return session->status().block.line == 4; });
         }},
        {"jog",
         [=, &t] {
             return session->jog(Axis::Y, 1) &&
                    t.serviceUntil([=, &t] { return t.status().state == MachineState::Jogging; });
         }},
        {"jogged away from a held program",
         [=, &t] {
             if (!session->startProgram(longMove, "L.H") || !atX(t.nominal(Axis::X))) return false;
             session->feedHold();
             if (!t.serviceUntil([=, &t] { return t.status().state == MachineState::Held; }))
                 return false;
             return session->jogIncrement(Axis::Y, 5) &&
                    t.serviceUntil([=, &t] { return t.status().state == MachineState::Jogging; });
         }},
        {"returning to the contour",
         [=, &t] {
             if (!session->startProgram(longMove, "L.H") || !atX(t.nominal(Axis::X))) return false;
             session->feedHold();
             if (!t.serviceUntil([=, &t] { return t.status().state == MachineState::Held; }) ||
                 !session->jogIncrement(Axis::Y, 20) ||
                 !t.serviceUntil([=, &t] { return t.status().state == MachineState::Jogging; }) ||
                 !t.serviceUntil([=, &t] { return t.status().state == MachineState::Held; }))
                 return false;
             session->cycleStart();
             return t.serviceUntil([=, &t] { return t.status().state == MachineState::Running; });
         }},
        {"homing",
         [=, &t] {
             return session->homeAll() &&
                    t.serviceUntil([=, &t] { return t.status().state == MachineState::Homing; });
         }},
    };
}

// One after the other on the same machine: each state is left by Stop to ready, from where the
// next one is reached.
TEST_F(MachineStopTest, StopLeavesEveryStateForReady) {
    for (const ReachableState& c : reachableStates(*this)) {
        SCOPED_TRACE(c.state);
        ASSERT_TRUE(ready()) << "not ready before";
        ASSERT_TRUE(c.reach()) << "state not reached";
        ASSERT_TRUE(stopsToReady());
        EXPECT_TRUE(spindleAndCoolantOff());
    }
}

// The same walk with the emergency stop: the drives stop at once, nothing is accepted until
// Machine on, then the machine is ready.
TEST_F(MachineStopTest, EmergencyStopLeavesEveryStateAndMachineOnReturnsToReady) {
    for (const ReachableState& c : reachableStates(*this)) {
        SCOPED_TRACE(c.state);
        ASSERT_TRUE(ready()) << "not ready before";
        ASSERT_TRUE(c.reach()) << "state not reached";
        session->emergencyStop();
        ASSERT_TRUE(
            serviceUntil([this] { return status().state == MachineState::EmergencyStop; }, 500ms));
        EXPECT_FALSE(session->busy());
        EXPECT_EQ(status().actualSpindleRpm, 0.0);
        EXPECT_FALSE(status().coolant);
        EXPECT_FALSE(session->jogIncrement(Axis::X, 1));
        EXPECT_FALSE(session->executeMdi("L X+0 R0 FMAX"));
        // The simulated drives' own quick-stop ramp takes milliseconds.
        serviceUntil([] { return false; }, 50ms);
        // The simulated button latches: the machine stays off until it is released.
        EXPECT_TRUE(session->emergencyStopPressed());
        EXPECT_TRUE(status().emergencyStopOpen);
        EXPECT_FALSE(session->machineOn()) << "on with the button pressed";
        session->releaseEmergencyStop();
        ASSERT_TRUE(serviceUntil([this] { return !status().emergencyStopOpen; }, 500ms));
        EXPECT_EQ(status().state, MachineState::EmergencyStop) << "released is not on";
        ASSERT_TRUE(session->machineOn());
        ASSERT_TRUE(serviceUntil([this] { return ready(); }, 2s));
        EXPECT_FALSE(session->machineOn()) << "on twice";
    }
}

}  // namespace
}  // namespace kerf::ui
