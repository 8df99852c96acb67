#include <QSignalSpy>
#include <QTreeWidget>
#include <chrono>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "motion/runtime/work_area_check.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
#include "ui/testrun/test_run_controller.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

// The messages of the list that name block 2 and the soft limit of X.
int refusalsOfBlock2(const MessagePanel& messages, const QString& prefix) {
    int count = 0;
    for (int i = 0; i < messages.messageCount(); ++i) {
        const QString text = messages.list()->topLevelItem(i)->text(1);
        if (text.startsWith(prefix) && text.contains(QStringLiteral("Block 2")) &&
            text.contains(QStringLiteral("axis X")) && text.contains(QStringLiteral("soft limit")))
            ++count;
    }
    return count;
}

// The operator sets a preset, then test-runs and runs a program whose block 2 is inside the
// work area only from the old origin: Test run refuses the block Program run refuses, with the
// machine's own message.
TEST(TestRunWorkAreaScreen, TestRunRefusesTheBlockProgramRunRefusesFromTheSamePreset) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_testrun_work_area");
    // Machine X+100 + 350 = 450 is beyond the mill's X limit +400 (machine X0 + 350 is not).
    std::ofstream(dir / "W.H") << "0 BEGIN PGM W MM\n"
                                  "1 L X+0 Y+0 Z+10 R0 FMAX\n"
                                  "2 L X+350 R0 FMAX\n"
                                  "3 END PGM W MM\n";
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    context.checkMoves = [config = context.machine](const Pose& origin) {
        return motion::makeWorkAreaCheck(config, origin);
    };
    MainWindow window(std::move(context));
    ASSERT_NE(window.session(), nullptr);
    ASSERT_TRUE(window.openProgram(dir / "W.H"));
    // The tool tip stands at the workpiece origin (machine X0): it becomes X-100.
    ASSERT_TRUE(window.session()->setPresetByEntry(Axis::X, -100.0));

    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    TestRunController* run = window.testRun();
    run->setSpeed(TestRunSpeed::Max);
    window.startTestRun();
    const auto interpreted = std::chrono::steady_clock::now() + 20s;
    while (run->state() != TestRunController::State::Failed &&
           run->state() != TestRunController::State::Finished &&
           std::chrono::steady_clock::now() < interpreted) {
        QCoreApplication::processEvents();
        std::this_thread::sleep_for(2ms);
    }
    EXPECT_EQ(run->state(), TestRunController::State::Failed);
    EXPECT_EQ(refusalsOfBlock2(*window.messages(), QStringLiteral("Test run: ")), 1);

    ASSERT_TRUE(window.modes().requestMachineMode(task::MachineMode::FullSequence));
    ASSERT_TRUE(window.softkeys()->pressId("ncStart"));
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (window.session()->runState() != task::RunState::Failed &&
           window.session()->runState() != task::RunState::Finished &&
           std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        std::this_thread::sleep_for(5ms);
    }
    EXPECT_EQ(window.session()->runState(), task::RunState::Failed);
    EXPECT_EQ(refusalsOfBlock2(*window.messages(), QString()), 2);
}

}  // namespace
}  // namespace kerf::ui
