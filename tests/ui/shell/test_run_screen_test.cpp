#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <cmath>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "motion/sim/simulated_clock.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "tests/support/machining_time_programs.h"
#include "ui/cycles/cycle_dialog.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/workspace.h"
#include "ui/status/status_tabs.h"
#include "ui/testrun/test_run_controller.h"
#include "ui/viewport/graphics_panel.h"

namespace kerf::ui {
namespace {

HmiContext contextIn(const std::filesystem::path& dir) {
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.machiningClock = motion::makeSimulatedClock;
    return context;
}

// On the offscreen platform the graphics panel has no 3D view; the test run itself, its
// softkeys, the machining time and the messages work the same.
TEST(TestRunScreen, StartRunsTheEditorsProgramAndReportsItsErrorsWithTheirLine) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_testrun");
    // Two feed moves: 10 mm at F600 (1 s) and 20 mm at F600 (2 s) after a 5 mm rapid.
    ASSERT_FALSE(writeFileAtomically(dir / "LINE.H",
                                     "0 BEGIN PGM LINE MM\n1 TOOL CALL 0 Z S1000\n"
                                     "2 L Z+5 R0 FMAX\n3 L X+10 R0 F600\n4 L Y+20 F600\n"
                                     "5 END PGM LINE MM\n")
                     .has_value());
    MainWindow window(contextIn(dir));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.openProgram(dir / "LINE.H"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    // Test run brings the graphics beside the program.
    EXPECT_EQ(window.workspace()->layoutKind(), WorkspaceLayout::ProgramGraphics);
    EXPECT_TRUE(window.graphics()->isVisible());

    TestRunController* run = window.testRun();
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testSpeed")));  // x10 -> x100
    EXPECT_EQ(run->speed(), TestRunSpeed::Times100);
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testSpeed")));  // -> max
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testStart")));
    ASSERT_TRUE(QTest::qWaitFor(
        [run] { return run->state() == TestRunController::State::Finished; }, 20000));
    // The time of the program run on the machine (simulated): more than the feeds' 3 s.
    const double programRunS = kerf::test::simulatedProgramRunS(
        dir / "LINE.H", window.program()->editor()->toPlainText().toStdString(), "mill");
    EXPECT_NEAR(run->machiningTimeS(), programRunS, 0.01 * programRunS);
    EXPECT_GT(run->machiningTimeS(), 3.0);
    EXPECT_TRUE(window.graphics()->timeLabel()->text().contains(
        GraphicsPanel::formatDuration(run->machiningTimeS())));

    // An error in the edited text: Start interprets the new text and stops at the bad line.
    ProgramEditor* editor = window.program()->editor();
    editor->setPlainText(
        QStringLiteral("0 BEGIN PGM LINE MM\n1 TOOL CALL 0 Z S1000\n"
                       "2 L Z+5 R0 FMAX\n3 NONSENSE\n4 END PGM LINE MM\n"));
    const int before = window.messages()->messageCount();
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testStart")));
    ASSERT_TRUE(
        QTest::qWaitFor([run] { return run->state() == TestRunController::State::Failed; }, 20000));
    EXPECT_GT(window.messages()->messageCount(), before);
    // The test run's message names line 4; activating it puts the editor there.
    QTreeWidget* list = window.messages()->list();
    int row = -1;
    for (int i = 0; i < list->topLevelItemCount(); ++i) {
        if (list->topLevelItem(i)->text(1).startsWith(QStringLiteral("Test run"))) row = i;
    }
    ASSERT_GE(row, 0);
    window.messages()->activate(row);
    EXPECT_EQ(editor->currentLine(), 4);
}

// Results that arrive for a program no longer shown must not land on the one shown: after
// another program is opened, the old test run (its toolpath, its state) is forgotten and the
// messages of the old program no longer jump into the new one.
TEST(TestRunScreen, OpeningAnotherProgramForgetsTheOldOnesTestRunAndLines) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_testrun_swap");
    ASSERT_FALSE(writeFileAtomically(dir / "BAD.H",
                                     "0 BEGIN PGM BAD MM\n1 L Z+5 R0 FMAX\n2 L X+10 R0 F600\n"
                                     "3 NONSENSE\n4 END PGM BAD MM\n")
                     .has_value());
    ASSERT_FALSE(
        writeFileAtomically(dir / "OK.H", "0 BEGIN PGM OK MM\n1 L Z+5 R0 FMAX\n2 END PGM OK MM\n")
            .has_value());
    MainWindow window(contextIn(dir));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.openProgram(dir / "BAD.H"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    TestRunController* run = window.testRun();
    ASSERT_TRUE(
        QTest::qWaitFor([run] { return run->state() == TestRunController::State::Failed; }, 20000));
    ASSERT_NE(run->program(), nullptr);
    // The test run's error names block 3 (line 4) of BAD.H.
    QTreeWidget* list = window.messages()->list();
    const auto testRunRow = [list] {
        for (int i = 0; i < list->topLevelItemCount(); ++i) {
            if (list->topLevelItem(i)->text(1).startsWith(QStringLiteral("Test run"))) return i;
        }
        return -1;
    };
    ASSERT_GE(testRunRow(), 0);
    EXPECT_EQ(list->topLevelItem(testRunRow())->text(2), QStringLiteral("3"));

    // Programming, then another program: the test run of BAD.H is dropped.
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    ASSERT_TRUE(window.openProgram(dir / "OK.H"));
    EXPECT_EQ(run->state(), TestRunController::State::Empty);
    EXPECT_EQ(run->program(), nullptr);
    EXPECT_EQ(run->stock(), nullptr);
    // The message stays, without its line: touching it leaves the editor where it is.
    ProgramEditor* editor = window.program()->editor();
    editor->goToLine(2);
    QSignalSpy jumps(window.messages(), &MessagePanel::lineActivated);
    const int row = testRunRow();
    ASSERT_GE(row, 0);
    EXPECT_TRUE(list->topLevelItem(row)->text(2).isEmpty());
    window.messages()->activate(row);
    EXPECT_EQ(jumps.count(), 0);
    EXPECT_EQ(editor->currentLine(), 2);
}

// The operator story on one window: write a drilling cycle through the CYCL DEF softkeys
// and its dialog, then check the program in Test run.
TEST(TestRunScreen, ACycleWrittenThroughTheDialogRunsInTestRun) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_cycle_testrun");
    ASSERT_FALSE(writeFileAtomically(dir / "DRILL.H",
                                     "0 BEGIN PGM DRILL MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
                                     "2 BLK FORM 0.2 X+100 Y+100 Z+0\n3 TOOL CALL 1 Z S3000\n"
                                     "4 L X+50 Y+50 Z+50 R0 FMAX M3\n5 END PGM DRILL MM\n")
                     .has_value());
    MainWindow window(contextIn(dir));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.openProgram(dir / "DRILL.H"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    ProgramEditor* editor = window.program()->editor();
    editor->goToLine(5);  // 1-based: block 4, the positioning above the hole

    // CYCL DEF -> drilling group -> 200, answered like an operator typing the values.
    QTimer::singleShot(0, [] {
        auto* dialog = qobject_cast<CycleDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        const char* values[] = {"2", "-10", "150", "5", "0", "0", "50", "0", "0"};
        for (int i = 0; i < 9; ++i)
            dialog->input(i)->setText(QString::fromLatin1(values[i]));
        dialog->accept();
    });
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("cyclDef")));
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("cycleGroup0")));
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("cycle200")));
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("cyclCall")));
    const QString text = editor->toPlainText();
    EXPECT_TRUE(text.contains(QStringLiteral("5 CYCL DEF 200 DRILLING ~"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("6 CYCL CALL\n7 END PGM DRILL MM")))
        << text.toStdString();

    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    TestRunController* run = window.testRun();
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testSpeed")));  // x10 -> x100
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testSpeed")));  // -> max
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testStart")));
    ASSERT_TRUE(QTest::qWaitFor(
        [run] { return run->state() == TestRunController::State::Finished; }, 20000));
    // Spec cycle 200 from Z+50 (surface 0, clearance 2, depth 10 in infeeds of 5): feed Z+2 -> Z-5
    // and Z-3 -> Z-10, 14 mm at F150 = 5.6 s, then rapids. The test run takes the time of the
    // program run on the machine (simulated).
    const double programRunS = kerf::test::simulatedProgramRunS(
        dir / "run" / "DRILL.H", editor->toPlainText().toStdString(), "mill");
    EXPECT_NEAR(run->machiningTimeS(), programRunS, 0.01 * programRunS);
    EXPECT_GT(run->machiningTimeS(), 5.6);
}

// The status tabs belong to the screen on view: after a test run of a G81 on the lathe, Automatic
// execution shows the machine's (nothing run yet), not the test run's cycle and M functions, and
// Simulation shows the test run's again (the machine screen showed "G81 ..." and "M3 M41").
TEST(TestRunScreen, TheMachineScreenDoesNotShowTheTestRunsStatus) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_testrun_status");
    ASSERT_FALSE(writeFileAtomically(dir / "TURN.PIM",
                                     "%TURN,MX,\nN10 G90 G95 G97 F0.2 S800 M41 M3\n"
                                     "N20 G00 X64 Z2\nN30 G81 X50 Z0 Q50 R-20 C2.5\nN40 M30\n")
                     .has_value());
    HmiContext context = contextIn(dir);
    context.machine = *machine::loadMachine("lathe");
    MainWindow window(context);
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.openProgram(dir / "TURN.PIM"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    TestRunController* run = window.testRun();
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testSpeed")));
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testSpeed")));
    ASSERT_TRUE(window.softkeys()->pressId(QStringLiteral("testStart")));
    ASSERT_TRUE(QTest::qWaitFor(
        [run] { return run->state() == TestRunController::State::Finished; }, 20000));
    const StatusTabs& tabs = *window.findChild<StatusTabs*>();
    const QString cycle = tabs.valueOf(StatusTabs::Tab::Program, QStringLiteral("Cycle"));
    EXPECT_TRUE(cycle.startsWith(QStringLiteral("G81"))) << cycle.toStdString();

    ASSERT_TRUE(window.modes().requestMachineMode(task::MachineMode::FullSequence));
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Program, QStringLiteral("Cycle")),
              QStringLiteral("none"));
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Program, QStringLiteral("M functions")),
              QStringLiteral("none"));

    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Program, QStringLiteral("Cycle")), cycle);
}

}  // namespace
}  // namespace kerf::ui
