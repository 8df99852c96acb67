// Return to the contour through the session: hold a program, jog away, cycle start returns to
// the interruption point and the program ends at its programmed end point.
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

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
class ContourReturnSessionTest : public testing::Test {
protected:
    ContourReturnSessionTest() {
        test::testApp();
        config = *machine::loadMachine("mill");
        session =
            std::make_unique<MachineSession>(config, test::connectSimulatedMachine(config), "");
    }
    bool serviceUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 10s) {
        return test::serviceUntil(*session, done, limit);
    }
    // Setpoints come to rest within a few filter lengths (17 ms).
    void settle() {
        serviceUntil([] { return false; }, 150ms);
    }
    double nominal(Axis a) const {
        return session->status().axes[static_cast<size_t>(axisIndex(a))].nominal;
    }

    machine::MachineConfig config;
    std::unique_ptr<MachineSession> session;
};

TEST_F(ContourReturnSessionTest, HoldJogAwayAndCycleStartEndsAtTheProgrammedEndPoint) {
    // 40 mm at 50 mm/s: 0.8 s, time enough to hold on the way.
    ASSERT_TRUE(session->startProgram(
        "0 BEGIN PGM R MM\n1 L X+40 Y+0 Z+0 R0 F3000\n2 END PGM R MM\n", "R.H"));
    ASSERT_TRUE(serviceUntil([this] { return nominal(Axis::X) > 10.0; }));
    // Jogging is refused while the program moves.
    EXPECT_FALSE(session->jogIncrement(Axis::Y, 1));
    session->feedHold();
    ASSERT_TRUE(serviceUntil([this] { return session->status().state == MachineState::Held; }));
    settle();
    const double heldX = nominal(Axis::X);
    ASSERT_LT(heldX, 39.0);

    session->setIncrementMm(2.5);
    ASSERT_TRUE(session->jogIncrement(Axis::Y, 1));
    // The jog ends in the hold, 2.5 mm off the path, X where it stopped.
    ASSERT_TRUE(serviceUntil([this] {
        return std::fabs(nominal(Axis::Y) - 2.5) < 1e-9 &&
               session->status().state == MachineState::Held;
    }));
    EXPECT_EQ(session->runState(), RunState::Held);
    EXPECT_NEAR(nominal(Axis::X), heldX, 1e-9);

    session->cycleStart();
    // Y goes back to the path before X moves on.
    bool xBeforeY = false;
    ASSERT_TRUE(serviceUntil([&] {
        if (nominal(Axis::X) > heldX + 1e-9 && std::fabs(nominal(Axis::Y)) > 1e-9) xBeforeY = true;
        return session->runState() == RunState::Finished;
    }));
    EXPECT_FALSE(xBeforeY);
    settle();
    EXPECT_NEAR(nominal(Axis::X), 40.0, 1e-6);
    EXPECT_NEAR(nominal(Axis::Y), 0.0, 1e-6);
    EXPECT_NEAR(nominal(Axis::Z), 0.0, 1e-6);
}

}  // namespace
}  // namespace kerf::ui
