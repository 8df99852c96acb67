// The status tabs follow a program the machine session runs (connected as MainWindow does).
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "session_service.h"
#include "simulated_machine.h"
#include "ui/session/machine_session.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;
using Tab = StatusTabs::Tab;

TEST(SessionStatus, TabsShowTheRunningProgramsState) {
    test::testApp();
    auto mill = machine::loadMachine("mill");
    ASSERT_TRUE(mill.ok());
    MachineSession session(*mill, test::connectSimulatedMachine(*mill), "");
    StatusTabs tabs;
    QObject::connect(&session, &MachineSession::programStatusChanged, &tabs,
                     &StatusTabs::setProgramStatus);
    ASSERT_TRUE(
        session.startProgram("0 BEGIN PGM S MM\n1 Q5 = 4\n2 CYCL DEF 7.0 DATUM SHIFT\n"
                             "3 CYCL DEF 7.1 X+2\n4 L X+1 Y+0 Z+0 R0 F500 M3\n"
                             "5 L X+2\n6 END PGM S MM\n",
                             "S.H"));
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (session.runState() != task::RunState::Finished &&
           session.runState() != task::RunState::Failed &&
           std::chrono::steady_clock::now() < deadline) {
        session.service();
        std::this_thread::sleep_for(2ms);
    }
    ASSERT_EQ(session.runState(), task::RunState::Finished);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Program"), "S.H");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Cycle"), "7 DATUM SHIFT");
    EXPECT_EQ(tabs.valueOf(Tab::Parameters, "Q5"), "4");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Datum shift X"), "2.000 mm");
}

TEST(SessionStatus, CoolantShowsWhatTheMachineExecutes) {
    // M8 with block 1, a program stop in block 2, M9 with block 3: the display says "on" while
    // the machine waits at the stop and "off" after the program ends.
    test::testApp();
    auto mill = machine::loadMachine("mill");
    ASSERT_TRUE(mill.ok());
    MachineSession session(*mill, test::connectSimulatedMachine(*mill), "");
    PositionDisplay display(*mill);
    QObject::connect(&session, &MachineSession::statusChanged, &display,
                     &PositionDisplay::setStatus);
    EXPECT_EQ(display.coolantText(), QStringLiteral("Coolant off"));
    ASSERT_TRUE(
        session.startProgram("0 BEGIN PGM C MM\n1 L X+1 Y+0 Z+0 R0 F500 M3 M8\n2 STOP\n"
                             "3 L X+2 M9\n4 END PGM C MM\n",
                             "C.H"));
    // The display follows the status the session emits while it is serviced.
    auto stateIs = [&session](task::RunState wanted) {
        return [&session, wanted] { return session.runState() == wanted; };
    };
    ASSERT_TRUE(test::serviceUntil(session, stateIs(task::RunState::Stopped), 10s));
    test::serviceUntil(
        session, [] { return false; }, 50ms);  // the status after the stop
    EXPECT_EQ(display.coolantText(), QStringLiteral("Coolant on"));
    session.cycleStart();
    ASSERT_TRUE(test::serviceUntil(session, stateIs(task::RunState::Finished), 10s));
    test::serviceUntil(
        session, [] { return false; }, 50ms);
    EXPECT_EQ(display.coolantText(), QStringLiteral("Coolant off"));
}

TEST(SessionStatus, LatheShowsCoolantAndTheConstantSurfaceSpeed) {
    // FAGOR: M8 is the coolant, G96 S200 a cutting speed of 200 m/min. At the M0 stop the tool
    // stands at X40 (diameter): the spindle turns 200000 / (pi 40) = 1592 rpm, shown as actual;
    // the programmed S is the cutting speed, not an rpm computed at the block's start.
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    MachineSession session(*lathe, test::connectSimulatedMachine(*lathe), "");
    PositionDisplay display(*lathe);
    QObject::connect(&session, &MachineSession::statusChanged, &display,
                     &PositionDisplay::setStatus);
    ASSERT_TRUE(
        session.startProgram("G90 G95 G71\nG92 S3000\nM41\nG00 X40 Z5\n"
                             "G96 S200 M3 M8\nG01 Z0 F0.2\nM0\nG01 Z-1\nM30\n",
                             "CSS.PIM"));
    auto stateIs = [&session](task::RunState wanted) {
        return [&session, wanted] { return session.runState() == wanted; };
    };
    ASSERT_TRUE(test::serviceUntil(session, stateIs(task::RunState::Stopped), 10s));
    test::serviceUntil(
        session, [] { return false; }, 50ms);
    EXPECT_EQ(display.coolantText(), QStringLiteral("Coolant on"));
    EXPECT_EQ(display.spindleText(), QStringLiteral("S 200 m/min (actual 1592 rpm)"));
    session.cycleStart();
    ASSERT_TRUE(test::serviceUntil(session, stateIs(task::RunState::Finished), 10s));
    test::serviceUntil(
        session, [] { return false; }, 50ms);
    EXPECT_EQ(display.coolantText(), QStringLiteral("Coolant off"));
}

}  // namespace
}  // namespace kerf::ui
