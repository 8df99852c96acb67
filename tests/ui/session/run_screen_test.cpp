#include <QSignalSpy>
#include <chrono>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/workspace.h"
#include "ui/status/position_display.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

// The run screen as the operator uses it: open a program, choose Program run full sequence,
// touch NC start; the position display follows the machine and the mode cannot change meanwhile.
TEST(RunScreen, NcStartRunsTheEditorsProgramOnTheMachine) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_run_screen");
    std::ofstream(dir / "R.H") << "0 BEGIN PGM R MM\n"
                                  "1 L X+12 Y-4 Z+0 R0 FMAX\n"
                                  "2 L X+20 F6000\n"
                                  "3 END PGM R MM\n";
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    MainWindow window(std::move(context));
    ASSERT_NE(window.session(), nullptr);
    ASSERT_TRUE(window.openProgram(dir / "R.H"));
    ASSERT_TRUE(window.modes().requestMachineMode(task::MachineMode::FullSequence));
    ASSERT_TRUE(window.softkeys()->pressId("ncStart"));
    EXPECT_TRUE(window.session()->busy());
    QSignalSpy refused(&window.modes(), &ModeController::refused);
    EXPECT_FALSE(window.modes().requestMachineMode(task::MachineMode::Manual));
    EXPECT_EQ(refused.count(), 1);
    // A picture of the run screen while the axes move, for the operator's eyes.
    window.resize(1280, 800);
    window.show();
    const auto moving = std::chrono::steady_clock::now() + 5s;
    while (window.session()->status().axes[0].nominal < 14.0 &&
           std::chrono::steady_clock::now() < moving) {
        QCoreApplication::processEvents();
        std::this_thread::sleep_for(2ms);
    }
    EXPECT_TRUE(window.grab().save("run_screen.png"));
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (window.session()->runState() != task::RunState::Finished &&
           std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        std::this_thread::sleep_for(5ms);
    }
    ASSERT_EQ(window.session()->runState(), task::RunState::Finished);
    // Let the drives settle, then show the nominal position: X from block 2, Y from block 1.
    DisplaySettings nominal;
    nominal.positionKind = PositionKind::Nominal;
    window.positions()->setDisplaySettings(nominal);
    for (int i = 0; i < 10; ++i) {
        QCoreApplication::processEvents();
        std::this_thread::sleep_for(20ms);
    }
    EXPECT_EQ(window.positions()->axisText(Axis::X), "+20.000");
    EXPECT_EQ(window.positions()->axisText(Axis::Y), "-4.000");
    EXPECT_TRUE(window.modes().requestMachineMode(task::MachineMode::Manual));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    EXPECT_EQ(window.workspace()->layoutKind(), WorkspaceLayout::Program);
}

TEST(RunScreen, AProgrammingStationHasNoMachine) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_run_station");
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.programmingStation = true;
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    MainWindow window(std::move(context));
    EXPECT_EQ(window.session(), nullptr);
}

}  // namespace
}  // namespace kerf::ui
