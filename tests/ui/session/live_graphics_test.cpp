// Program run's graphics: the program's toolpath with the tool where the machine is, the part
// executed drawn over it, the stock cut along the drives' positions, and the progress in the
// planner's machining time; the status tabs at the block the machine executes.
#include <QLabel>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "graphics/stock/progressive_stock.h"
#include "motion/sim/simulated_clock.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
#include "ui/shell/workspace.h"
#include "ui/status/status_tabs.h"
#include "ui/testrun/test_run_controller.h"
#include "ui/viewport/graphics_panel.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

// Tool 1 of TOOL.T is a drill of L 80 and R 2.5 with a 118° point. The test machine's spindle
// stands at the workpiece origin: up first, then the tool. A 7 mm plunge at F300 (1.4 s), a 30
// mm slot 2 mm deep at F900 (2 s), a retract. Toolpath points: 0 the start (0, 0, 0), then one
// per move: 1 (0, 0, 100), 2 (0, 0, 5), 3 (10, 10, 5), 4 (10, 10, -2), 5 (40, 10, -2),
// 6 (40, 10, 5).
const char* kSlot =
    "0 BEGIN PGM SLOT MM\n"
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
    "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
    "3 L Z+100 R0 FMAX\n"
    "4 TOOL CALL 1 Z S2000\n"
    "5 L Z+5 R0 FMAX\n"
    "6 L X+10 Y+10 R0 FMAX\n"
    "7 L Z-2 R0 F300\n"
    "8 L X+40 F900\n"
    "9 L Z+5 R0 FMAX\n"
    "10 END PGM SLOT MM\n";

bool processUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 20s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

class LiveGraphics : public testing::Test {
protected:
    LiveGraphics() {
        test::testApp();
        dir = kerf::test::uniqueTempDir("hmi_live_graphics");
        std::filesystem::copy_file(
            std::filesystem::path(KERF_SOURCE_DIR) / "tests/graphics/programs/TOOL.T",
            dir / "TOOL.T");
        std::ofstream(dir / "SLOT.H") << kSlot;
        HmiContext context;
        context.machine = *machine::loadMachine("mill");
        context.ncRoot = dir;
        context.recoveryFolder = dir / "recovery";
        context.motion = [config = context.machine] {
            return test::connectSimulatedMachine(config);
        };
        context.machiningClock = motion::makeSimulatedClock;
        window = std::make_unique<MainWindow>(std::move(context));
        window->resize(1280, 800);
        window->show();
    }
    double nominal(size_t axis) const { return window->session()->status().axes[axis].nominal; }

    std::filesystem::path dir;
    std::unique_ptr<MainWindow> window;
};

TEST_F(LiveGraphics, ProgramRunDrawsWhereTheMachineIsAndCountsDownThePlannersTime) {
    ASSERT_TRUE(window->openProgram(dir / "SLOT.H"));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    window->workspace()->setLayoutKind(WorkspaceLayout::ProgramGraphics);
    TestRunController* live = window->liveRun();
    ASSERT_NE(live, nullptr);
    // The machine screen shows the machine's run, not the test run.
    EXPECT_EQ(&window->graphics()->playback(), live);
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    EXPECT_TRUE(live->followsMachine());

    double lastPercent = -1.0;
    double lastRemaining = std::numeric_limits<double>::infinity();
    bool monotone = true;
    bool sawSlot = false;
    auto watch = [&] {
        if (live->state() != TestRunController::State::Following) return;
        monotone = monotone && live->progressPercent() >= lastPercent &&
                   live->remainingTimeS() <= lastRemaining;
        lastPercent = live->progressPercent();
        lastRemaining = live->remainingTimeS();
        const auto block = live->currentBlock();
        const double x = nominal(0);
        if (!block || block->line != 9 || x < 18.0 || x > 32.0) return;
        // In the slot: points 0..4 done, the tip on the segment to point 5 near the machine's
        // commanded X (looked at 40 ms apart at most, at 15 mm/s: 0.6 mm, plus one service).
        sawSlot = true;
        const TestRunController::ExecutedPart part = live->executedPart();
        EXPECT_EQ(part.fromPoint, 0u);
        EXPECT_EQ(part.reached.pointsDone, 5u);
        EXPECT_NEAR(part.reached.tip.x(), x, 1.5);
        EXPECT_NEAR(part.reached.tip.y(), 10.0, 1e-6);
        EXPECT_NEAR(part.reached.tip.z(), -2.0, 1e-6);
        // Four path segments and the one to the tip, over the path.
        EXPECT_EQ(window->graphics()->scene().stats().executedSegments, 5u);
        // The tool where the drives are, not on the program's path by the clock.
        EXPECT_NEAR(live->toolPosition().x(), window->session()->status().axes[0].actual, 1.5);
        EXPECT_NEAR(live->toolPosition().z(), -2.0, 0.05);
        // Left: the rest of the slot at F900 (15 mm/s) and the retract (a rapid of 7 mm:
        // under 0.4 s with its acceleration), as the planner times them.
        const double slotLeftS = (40.0 - part.reached.tip.x()) / 15.0;
        EXPECT_GT(live->remainingTimeS(), slotLeftS);
        EXPECT_LT(live->remainingTimeS(), slotLeftS + 0.6);
        EXPECT_TRUE(window->graphics()->timeLabel()->text().startsWith("Block 8"))
            << window->graphics()->timeLabel()->text().toStdString();
    };
    ASSERT_TRUE(processUntil([&] {
        watch();
        return window->session()->runState() == task::RunState::Finished;
    }));
    ASSERT_TRUE(processUntil([&] { return live->state() == TestRunController::State::Finished; }));
    EXPECT_TRUE(sawSlot);
    EXPECT_TRUE(monotone);
    EXPECT_DOUBLE_EQ(live->progressPercent(), 100.0);
    EXPECT_DOUBLE_EQ(live->remainingTimeS(), 0.0);
    // The feeds alone take 3.4 s; the planner's time adds the rapids and the accelerations.
    EXPECT_GT(live->machiningTimeS(), 3.4);
    EXPECT_LT(live->machiningTimeS(), 7.0);
    EXPECT_EQ(live->executedPart().reached.pointsDone, 7u);
    EXPECT_TRUE(window->graphics()->timeLabel()->text().contains("100 %"))
        << window->graphics()->timeLabel()->text().toStdString();

    // The stock was cut where the drives went: a slot 2 mm deep from X10 to X40 with round ends,
    // in the drill's shape: a cylinder of R 2.5 down to the point's 118° cone (h = R / tan 59°).
    ASSERT_NE(live->stock(), nullptr);
    ASSERT_TRUE(live->stock()->waitFinished(10s));
    const double r = 2.5;
    const double h = r / std::tan(59.0 * std::numbers::pi / 180.0);
    const double section = 2.0 * r * (2.0 - h) + r * h;                    // across the slot
    const double ends = std::numbers::pi * r * r * ((2.0 - h) + h / 3.0);  // the tool's own
    const double expected = 30.0 * section + ends;
    EXPECT_NEAR(live->stock()->latest()->removedVolumeMm3, expected, 0.04 * expected);
}

// At 50 % feed override the slot takes twice as long: the time remaining says so while the
// machine is in it (the retract is a rapid, whose override stays at 100 %).
TEST_F(LiveGraphics, TheTimeRemainingFollowsTheFeedOverride) {
    ASSERT_TRUE(window->openProgram(dir / "SLOT.H"));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    TestRunController* live = window->liveRun();
    window->session()->setFeedOverride(0.5);
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    bool sawSlot = false;
    ASSERT_TRUE(processUntil(
        [&] {
            const auto block = live->currentBlock();
            const double x = nominal(0);
            if (live->state() == TestRunController::State::Following && block && block->line == 9 &&
                x > 18.0 && x < 32.0) {
                sawSlot = true;
                // The rest of the slot at 7.5 mm/s instead of 15, then a rapid of 7 mm.
                const double slotLeftS = (40.0 - live->executedPart().reached.tip.x()) / 7.5;
                EXPECT_GT(live->remainingTimeS(), slotLeftS - 0.1);
                EXPECT_LT(live->remainingTimeS(), slotLeftS + 0.8);
            }
            return window->session()->runState() == task::RunState::Finished;
        },
        40s));
    EXPECT_TRUE(sawSlot);
}

// Two fast circles of R 3 with the 10 mm end mill (tool 2), looked at only every 150 ms: the
// looks are a good part of the circle apart, and the stock must be cut along the circle, not
// along the chords between them. Swept: a disk of R 3 + 5 = 8, 2 mm deep.
TEST_F(LiveGraphics, TheStockIsCutAlongThePathTheMachineFollowsBetweenTwoLooks) {
    std::ofstream(dir / "CIRC.H") << "0 BEGIN PGM CIRC MM\n"
                                     "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
                                     "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
                                     "3 L Z+100 R0 FMAX\n"
                                     "4 TOOL CALL 2 Z S3000\n"
                                     "5 CC X+30 Y+30\n"
                                     "6 L X+33 Y+30 Z+5 R0 FMAX\n"
                                     "7 L Z-2 R0 F3000\n"
                                     "8 C X+33 Y+30 DR+ F6000\n"
                                     "9 C X+33 Y+30 DR+\n"
                                     "10 L Z+5 R0 FMAX\n"
                                     "11 END PGM CIRC MM\n";
    ASSERT_TRUE(window->openProgram(dir / "CIRC.H"));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    TestRunController* live = window->liveRun();
    live->setFollowIntervalMs(150);
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    ASSERT_TRUE(processUntil([&] { return live->state() == TestRunController::State::Finished; }));
    ASSERT_NE(live->stock(), nullptr);
    ASSERT_TRUE(live->stock()->waitFinished(10s));
    const double expected = 2.0 * std::numbers::pi * 8.0 * 8.0;
    EXPECT_NEAR(live->stock()->latest()->removedVolumeMm3, expected, 0.015 * expected);
}

// The panel starts in Manual operation with the positions and the status on the screen; Test run
// must still bring the graphics beside the program (it showed the program alone).
TEST_F(LiveGraphics, TestRunFromAMachineModeShowsTheGraphicsBesideTheProgram) {
    ASSERT_TRUE(window->openProgram(dir / "SLOT.H"));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::PositionsStatus);
    window->modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::ProgramGraphics);
    EXPECT_TRUE(window->graphics()->isVisible());
    // Programming keeps the graphics the operator chose to see (docs/hmi.md).
    window->modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::ProgramGraphics);
    // Back at the machine, jogging needs the positions again (the graphics stayed).
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::PositionsStatus);
}

// Each machine mode brings back the layout the operator chose in it with the layout key.
TEST_F(LiveGraphics, EachMachineModeKeepsTheLayoutChosenInIt) {
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::ProgramStatus);
    // Screen layout: program + status -> positions + status -> program -> program + graphics.
    for (int press = 0; press < 3; ++press)
        ASSERT_TRUE(window->softkeys()->pressId(QStringLiteral("layout")));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::ProgramGraphics);
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::PositionsStatus);
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::ProgramGraphics);
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::SingleBlock));
    EXPECT_EQ(window->workspace()->layoutKind(), WorkspaceLayout::ProgramStatus);
}

}  // namespace
}  // namespace kerf::ui
