// The machine screens in the window: a program run shows the program following the executing
// block next to the positions; Manual operation and the handwheel on the softkeys.
#include <QFileSystemModel>
#include <QPushButton>
#include <QTreeView>
#include <chrono>
#include <fstream>
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/files/file_manager.h"
#include "ui/shell/machine_keys.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/workspace.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

bool processUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 10s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

// The line the follower lit up, if any.
std::optional<int> highlightedLine(const ProgramEditor& editor) {
    for (const QTextEdit::ExtraSelection& s : editor.extraSelections()) {
        if (s.format.property(QTextFormat::FullWidthSelection).toBool() &&
            s.format.background().color() != Qt::transparent)
            return s.cursor.blockNumber() + 1;
    }
    return std::nullopt;
}

class MachineScreens : public testing::Test {
protected:
    MachineScreens() {
        test::testApp();
        dir = kerf::test::uniqueTempDir("hmi_machine_screens");
        HmiContext context;
        context.machine = *machine::loadMachine("mill");
        context.ncRoot = dir;
        context.recoveryFolder = dir / "recovery";
        context.motion = [config = context.machine] {
            return test::connectSimulatedMachine(config);
        };
        window = std::make_unique<MainWindow>(std::move(context));
        window->resize(1280, 800);
        window->show();
    }
    double x() const { return window->session()->status().axes[0].nominal; }

    std::filesystem::path dir;
    std::unique_ptr<MainWindow> window;
};

TEST_F(MachineScreens, AProgramRunShowsTheProgramFollowingTheExecutingBlock) {
    // Blocks 2 and 3 each take 1 s (10 mm at 600 mm/min): block 2 is on line 3, block 3 on 4.
    std::ofstream(dir / "F.H") << "0 BEGIN PGM F MM\n"
                                  "1 L X+0 Y+0 Z+0 R0 FMAX\n"
                                  "2 L X+10 F600\n"
                                  "3 L X+20 F600\n"
                                  "4 END PGM F MM\n";
    ASSERT_TRUE(window->openProgram(dir / "F.H"));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    // Program run: the program, the positions and the status tabs, all on the screen.
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::ProgramStatus);
    EXPECT_TRUE(window->program()->isVisibleTo(window.get()));
    EXPECT_TRUE(window->positions()->isVisibleTo(window.get()));
    EXPECT_TRUE(window->findChild<StatusTabs*>()->isVisibleTo(window.get()));
    ProgramEditor* editor = window->program()->editor();
    EXPECT_FALSE(editor->isReadOnly());

    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    ASSERT_TRUE(processUntil([&] { return x() > 3.0; }));
    ASSERT_LT(x(), 7.0);
    EXPECT_EQ(editor->currentLine(), 3);
    EXPECT_EQ(highlightedLine(*editor), 3);
    EXPECT_TRUE(editor->isReadOnly());
    EXPECT_TRUE(window->grab().save("program_run_screen.png"));
    ASSERT_TRUE(processUntil([&] { return x() > 13.0; }));
    ASSERT_LT(x(), 17.0);
    EXPECT_EQ(editor->currentLine(), 4);
    EXPECT_EQ(highlightedLine(*editor), 4);

    ASSERT_TRUE(processUntil([&] { return !window->session()->busy(); }));
    processUntil([] { return false; }, 100ms);
    EXPECT_FALSE(editor->isReadOnly());
    EXPECT_EQ(highlightedLine(*editor), std::nullopt);

    // Manual operation: the positions and the overrides beside the status.
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::PositionsStatus);
    EXPECT_FALSE(window->program()->isVisibleTo(window.get()));
    EXPECT_TRUE(window->grab().save("manual_screen.png"));
    window->modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::Program);
}

TEST_F(MachineScreens, TheHandwheelKeysChooseTheAxisAndTheStep) {
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Handwheel));
    MachineSession* session = window->session();
    ASSERT_EQ(session->handwheelAxis(), Axis::X);
    // The mill's axes in order: X, Y, Z.
    ASSERT_TRUE(window->softkeys()->pressId("handwheelAxis"));
    EXPECT_EQ(session->handwheelAxis(), Axis::Y);
    // x1, x10, x100.
    ASSERT_TRUE(window->softkeys()->pressId("handwheelFactor"));
    ASSERT_TRUE(window->softkeys()->pressId("handwheelFactor"));
    EXPECT_EQ(session->handwheelFactor(), 100);
    // One detent at x100: 0.1 mm on Y.
    ASSERT_TRUE(window->softkeys()->pressId("handwheelPlus"));
    const auto y = [&] { return session->status().axes[1].nominal; };
    processUntil([&] { return y() > 0.0999; }, 5s);
    processUntil([] { return false; }, 150ms);
    EXPECT_NEAR(y(), 0.1, 1e-5);
    // Manual's functions are on the handwheel screen too.
    EXPECT_TRUE(window->softkeys()->pressId("coolantOn"));
}

TEST(MachineScreensFiles, TheTablesFilterIncludesTouchProbeTables) {
    test::testApp();
    FileManager files(kerf::test::uniqueTempDir("hmi_tp_filter"));
    files.setFilter(FileManager::Filter::Tables);
    auto* model = qobject_cast<QFileSystemModel*>(files.view()->model());
    ASSERT_NE(model, nullptr);
    EXPECT_TRUE(model->nameFilters().contains("*.tp"));
}

TEST_F(MachineScreens, TheEmergencyStopKeyStopsAProgramAndMachineOnSwitchesTheMachineOn) {
    std::ofstream(dir / "E.H") << "0 BEGIN PGM E MM\n1 L X+40 Y+0 Z+0 R0 F600 M3\n"
                                  "2 END PGM E MM\n";
    ASSERT_TRUE(window->openProgram(dir / "E.H"));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    MachineKeys* keys = window->machineKeys();
    ASSERT_TRUE(keys->emergencyStopKey()->isVisibleTo(window.get()));
    ASSERT_TRUE(keys->machineOnKey()->isVisibleTo(window.get()));
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    ASSERT_TRUE(processUntil([&] { return x() > 2.0; }));
    MachineSession* session = window->session();
    keys->emergencyStopKey()->click();
    ASSERT_TRUE(processUntil(
        [&] { return session->status().state == task::MachineState::EmergencyStop; }, 1s));
    const double stoppedAt = x();
    processUntil([] { return false; }, 200ms);
    EXPECT_NEAR(x(), stoppedAt, 0.01) << "the axes move after the emergency stop";
    EXPECT_LT(x(), 40.0);
    EXPECT_FALSE(session->busy());
    // NC start is refused until the machine is on again.
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    processUntil([] { return false; }, 100ms);
    EXPECT_EQ(session->status().state, task::MachineState::EmergencyStop);
    keys->machineOnKey()->click();
    ASSERT_TRUE(
        processUntil([&] { return session->status().state == task::MachineState::Idle; }, 2s));
    EXPECT_TRUE(window->grab().save("emergency_stop_screen.png"));
}

}  // namespace
}  // namespace kerf::ui
