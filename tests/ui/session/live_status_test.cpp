// Program run's status displays show the block the machine executes, not the interpreter's
// read-ahead: the status tabs, and the programmed feed inside a cycle and per revolution; the
// TOOL tab after an MDI TOOL CALL.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "motion/sim/simulated_clock.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"
#include "ui/testrun/test_run_controller.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

bool processUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 20s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

class LiveStatus : public testing::Test {
protected:
    void open(const char* machineName, const std::string& file, const std::string& text) {
        test::testApp();
        dir = kerf::test::uniqueTempDir("hmi_live_status");
        std::filesystem::copy_file(
            std::filesystem::path(KERF_SOURCE_DIR) / "tests/graphics/programs/TOOL.T",
            dir / "TOOL.T");
        std::ofstream(dir / file) << text;
        HmiContext context;
        context.machine = *machine::loadMachine(machineName);
        context.ncRoot = dir;
        context.recoveryFolder = dir / "recovery";
        context.motion = [config = context.machine] {
            return test::connectSimulatedMachine(config);
        };
        context.machiningClock = motion::makeSimulatedClock;
        window = std::make_unique<MainWindow>(std::move(context));
        window->resize(1280, 800);
        window->show();
        ASSERT_TRUE(window->openProgram(dir / file));
        ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    }
    StatusTabs& tabs() const { return *window->findChild<StatusTabs*>(); }
    const task::MachineStatus& status() const { return window->session()->status(); }
    bool finished() const { return window->session()->runState() == task::RunState::Finished; }

    std::filesystem::path dir;
    std::unique_ptr<MainWindow> window;
};

// The interpreter reads far ahead of the machine: it has called tool 2 long before the machine
// cuts block 3 with tool 1.
TEST_F(LiveStatus, TheToolTabShowsTheToolOfTheBlockTheMachineCutsNotOfTheReadAhead) {
    open("mill", "TOOLS.H",
         "0 BEGIN PGM TOOLS MM\n"
         "1 L Z+100 R0 FMAX\n"
         "2 TOOL CALL 1 Z S1000\n"
         "3 L X+30 R0 F900\n"
         "4 TOOL CALL 2 Z S2000\n"
         "5 L X+0 R0 FMAX\n"
         "6 END PGM TOOLS MM\n");
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    bool sawBlock3 = false;
    ASSERT_TRUE(processUntil([&] {
        if (status().block.line == 4 && status().axes[0].nominal > 10.0 &&
            status().axes[0].nominal < 20.0) {
            sawBlock3 = true;
            EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Block"), "3");
            EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Tool, "Tool"), "1");
            EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Spindle"), "S 1000 rpm");
        }
        return finished();
    }));
    EXPECT_TRUE(sawBlock3);
    ASSERT_TRUE(
        processUntil([&] { return tabs().valueOf(StatusTabs::Tab::Tool, "Tool") == "2"; }, 5s));
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Spindle"), "S 2000 rpm");
}

// Program run single block: at each stop every display shows the block just executed, with
// its M functions done (the M5 M9 of `L Z+40 R0 FMAX M5 M9` before the stop), not the tool
// and spindle the interpreter has read ahead (TOOL CALL 2 S3000).
TEST_F(LiveStatus, AtASingleBlockStopTheDisplaysShowTheBlockJustExecuted) {
    open("mill", "STEP.H",
         "0 BEGIN PGM STEP MM\n"
         "1 TOOL CALL 1 Z S2000\n"
         "2 L X+0 Y+0 Z+10 R0 F3000 M3 M8\n"
         "3 L Z+40 R0 FMAX M5 M9\n"
         "4 TOOL CALL 2 Z S3000\n"
         "5 L X+20 R0 F600 M3\n"
         "6 END PGM STEP MM\n");
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::SingleBlock));
    PositionDisplay& positions = *window->positions();
    auto stoppedAt = [&](double z) {
        return processUntil([&] {
            return status().state == task::MachineState::Stopped &&
                   std::fabs(status().axes[2].nominal - z) < 1e-6;
        });
    };
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    ASSERT_TRUE(stoppedAt(10.0));
    // The spindle reaches 2000 rpm while the machine waits (3000 rpm/s).
    ASSERT_TRUE(
        processUntil([&] { return positions.spindleText() == "S 2000 (actual 2000) rpm"; }, 5s))
        << positions.spindleText().toStdString();
    EXPECT_EQ(positions.coolantText(), "Coolant on");
    EXPECT_EQ(positions.toolText(), "T 1");
    ASSERT_TRUE(
        processUntil([&] { return tabs().valueOf(StatusTabs::Tab::Program, "Block") == "2"; }, 5s));
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "M functions"), "M3 M8");

    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    ASSERT_TRUE(stoppedAt(40.0));
    EXPECT_EQ(positions.spindleText(), "S 0 (actual 0) rpm");
    EXPECT_EQ(positions.coolantText(), "Coolant off");
    EXPECT_EQ(positions.toolText(), "T 1");
    ASSERT_TRUE(
        processUntil([&] { return tabs().valueOf(StatusTabs::Tab::Program, "Block") == "3"; }, 5s));
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "M functions"), "M5 M9");
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Tool, "Tool"), "1");
    // It waits there: nothing of blocks 4 and 5 has run.
    processUntil([] { return false; }, 300ms);
    EXPECT_EQ(status().state, task::MachineState::Stopped);
    EXPECT_EQ(positions.toolText(), "T 1");
    EXPECT_EQ(positions.spindleText(), "S 0 (actual 0) rpm");
}

// Cycle 200 plunges at its own feed Q206 = 150 (the program's F is 900).
TEST_F(LiveStatus, TheFeedInsideACycleIsTheCyclesFeed) {
    open("mill", "DRILL.H",
         "0 BEGIN PGM DRILL MM\n"
         "1 L Z+100 R0 FMAX\n"
         "2 TOOL CALL 1 Z S1000\n"
         "3 L X+10 Y+10 Z+5 R0 F900 M3\n"
         "4 CYCL DEF 200 DRILLING ~\n"
         "  Q200=2 ;SET-UP CLEARANCE ~\n"
         "  Q201=-6 ;DEPTH ~\n"
         "  Q206=150 ;FEED RATE FOR PLNGNG ~\n"
         "  Q202=6 ;PLUNGING DEPTH ~\n"
         "  Q210=0 ;DWELL TIME AT TOP ~\n"
         "  Q203=+0 ;SURFACE COORDINATE ~\n"
         "  Q204=5 ;2ND SET-UP CLEARANCE ~\n"
         "  Q211=0 ;DWELL TIME AT DEPTH\n"
         "5 CYCL CALL\n"
         "6 END PGM DRILL MM\n");
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    bool sawPlunge = false;
    ASSERT_TRUE(processUntil([&] {
        // Inside the hole at the plunge's speed (not the rapid retract): the plunge at Q206.
        const double actual = status().actualFeedMmPerMin;
        if (status().block.line == 14 && status().axes[2].nominal < -1.0 &&
            status().axes[2].nominal > -5.0 && actual > 100.0 && actual < 200.0) {
            sawPlunge = true;
            EXPECT_TRUE(window->positions()->feedText().startsWith("F 150 (actual "))
                << window->positions()->feedText().toStdString();
        }
        return finished();
    }));
    EXPECT_TRUE(sawPlunge);
}

// G95 on the lathe: F 0.5 mm/rev at S 1500 is 750 mm/min along the path.
TEST_F(LiveStatus, APerRevolutionFeedIsShownInMillimetresPerRevolution) {
    open("lathe", "TURN.PIM",
         "%TURN,MX,\n"
         "N10 G90 G00 X70 Z5\n"
         "N20 G95 G97 S1500 M3\n"
         "N30 G01 Z-25 F0.5\n"
         "N40 G00 X80\n"
         "N50 M30\n");
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    bool sawCut = false;
    ASSERT_TRUE(processUntil([&] {
        if (status().block.line == 4 && status().axes[2].nominal < -5.0 &&
            status().axes[2].nominal > -20.0) {
            sawCut = true;
            const QString text = window->positions()->feedText();
            EXPECT_TRUE(text.startsWith("F 0.500 (actual ")) << text.toStdString();
            EXPECT_TRUE(text.endsWith(") mm/rev")) << text.toStdString();
        }
        return finished();
    }));
    EXPECT_TRUE(sawCut);
}

TEST_F(LiveStatus, TheToolTabShowsTheToolOfAnMdiToolCall) {
    open("mill", "EMPTY.H", "0 BEGIN PGM EMPTY MM\n1 END PGM EMPTY MM\n");
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Mdi));
    ASSERT_TRUE(window->session()->executeMdi("TOOL CALL 3 Z S1200"));
    ASSERT_TRUE(
        processUntil([&] { return window->session()->runState() == task::RunState::Finished; }));
    ASSERT_TRUE(
        processUntil([&] { return tabs().valueOf(StatusTabs::Tab::Tool, "Tool") == "3"; }, 2s))
        << tabs().valueOf(StatusTabs::Tab::Tool, "Tool").toStdString();
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Tool, "R"), "3.000 mm");
}

// NC start of another program: its status comes from Program run's preparation, which takes
// seconds for a long program (40 s for 60 000 blocks on a busy machine). Until it is ready the
// tabs showed the program run before (its name, cycle 200, its tool) while the new one ran.
TEST_F(LiveStatus, AtNcStartTheTabsLeaveTheProgramRunBefore) {
    open("mill", "DRILL.H",
         "0 BEGIN PGM DRILL MM\n"
         "1 L Z+100 R0 FMAX\n"
         "2 TOOL CALL 1 Z S2000\n"
         "3 CYCL DEF 200 DRILLING\n"
         "  Q200=2 ;SET-UP CLEARANCE\n"
         "  Q201=-3 ;DEPTH\n"
         "  Q206=300 ;FEED RATE FOR PLNGNG\n"
         "  Q202=3 ;PLUNGING DEPTH\n"
         "  Q210=0 ;DWELL TIME AT TOP\n"
         "  Q203=+0 ;SURFACE COORDINATE\n"
         "  Q204=10 ;2ND SET-UP CLEARANCE\n"
         "  Q211=0 ;DWELL TIME AT DEPTH\n"
         "  Q395=0 ;DEPTH REFERENCE\n"
         "4 L X+10 Y+10 R0 FMAX M3\n"
         "5 CYCL CALL\n"
         "6 L Z+100 R0 FMAX M5\n"
         "7 END PGM DRILL MM\n");
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    ASSERT_TRUE(processUntil([&] {
        return finished() && tabs().valueOf(StatusTabs::Tab::Program, "Cycle") == "200 DRILLING";
    }));
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Program"), "DRILL.H");
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Tool, "Tool"), "1");

    std::ofstream(dir / "MOVE.H") << "0 BEGIN PGM MOVE MM\n1 L X+20 R0 F3000\n"
                                     "2 END PGM MOVE MM\n";
    ASSERT_TRUE(window->openProgram(dir / "MOVE.H"));
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    // The preparation has not come back (no event has been processed since NC start).
    ASSERT_EQ(window->liveRun()->state(), TestRunController::State::Interpreting);
    EXPECT_TRUE(tabs().preparing());
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Program"), "MOVE.H");
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Status"),
              "follows when the program is prepared");
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Cycle"), "");  // no row: not known yet
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Tool, "Tool"), "");
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Tool, "Status"),
              "follows when the program is prepared");

    // Prepared, the tabs show the new program at the machine's block.
    ASSERT_TRUE(processUntil([&] { return finished() && !tabs().preparing(); }));
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Program"), "MOVE.H");
    EXPECT_EQ(tabs().valueOf(StatusTabs::Tab::Program, "Cycle"), "none");
    EXPECT_FALSE(tabs().valueOf(StatusTabs::Tab::Program, "Block").isEmpty());
}

}  // namespace
}  // namespace kerf::ui
