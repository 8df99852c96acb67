// The machine screens in the window: a program run shows the program following the executing
// block next to the positions; Manual operation and the handwheel on the softkeys.
#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QFileSystemModel>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
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
#include "ui/shell/mdi_dialog.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
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
    MachineScreens() { openWindow(true); }
    void openWindow(bool referenceRequired, test::Reference reference = test::Reference::Done) {
        test::testApp();
        window.reset();
        dir = kerf::test::uniqueTempDir("hmi_machine_screens");
        HmiContext context;
        context.machine = *machine::loadMachine("mill");
        context.machine.referenceRequired = referenceRequired;
        context.ncRoot = dir;
        context.recoveryFolder = dir / "recovery";
        context.motion = [config = context.machine, reference] {
            return test::connectSimulatedMachine(config, reference);
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

// A message whose cause is gone leaves the message line, as a TNC clears an error when its
// cause is removed; CE clears the one shown; newer errors are not hidden by older ones.
TEST_F(MachineScreens, AMessageLeavesTheLineWhenItsCauseIsGone) {
    openWindow(true, test::Reference::Required);
    std::ofstream(dir / "F.H") << "0 BEGIN PGM F MM\n"
                                  "1 L X+0 Y+0 Z+250 R0 FMAX\n"
                                  "2 END PGM F MM\n";
    ASSERT_TRUE(window->openProgram(dir / "F.H"));
    MessagePanel* messages = window->messages();
    messages->clearMessages();
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    const QString notReferenced = QStringLiteral("not referenced");
    EXPECT_TRUE(messages->line()->text().contains(notReferenced))
        << messages->line()->text().toStdString();

    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    ASSERT_TRUE(window->softkeys()->pressId("homeAll"));
    ASSERT_TRUE(processUntil([&] { return window->session()->referenced(); }, 30s));
    ASSERT_TRUE(processUntil([&] { return !window->session()->busy(); }));
    // The axes are referenced: the error has left the line (it stays in the list, greyed).
    EXPECT_FALSE(messages->line()->text().contains(notReferenced))
        << messages->line()->text().toStdString();
    EXPECT_EQ(messages->standingCount(), 0);
    EXPECT_GE(messages->messageCount(), 1);

    // An event has no cause that goes: CE clears it from the line, and the one before shows.
    messages->addMessage(Severity::Error, QStringLiteral("older event"), 0);
    messages->addMessage(Severity::Error, QStringLiteral("newer event"), 0);
    EXPECT_TRUE(messages->line()->text().contains(QStringLiteral("newer event")));
    messages->clearKey()->click();
    EXPECT_TRUE(messages->line()->text().contains(QStringLiteral("older event")));
    messages->clearKey()->click();
    EXPECT_EQ(messages->standingCount(), 0);
    EXPECT_FALSE(messages->clearKey()->isEnabled());
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

// The text of the key with this id on whichever row of the softkey bar holds it, empty if none.
QString keyText(SoftkeyBar& bar, const QString& id) {
    for (int row = 0; row < bar.rowCount(); ++row) {
        bar.showRow(row);
        for (int i = 0; i < SoftkeyBar::kKeys; ++i)
            if (bar.keyId(i) == id) return bar.keyButton(i)->text();
    }
    return {};
}

// Answers the next number dialog with `value`, as the operator would type it.
void answerNumberDialog(int value) {
    QTimer::singleShot(0, [value] {
        auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        dialog->setIntValue(value);
        dialog->accept();
    });
}

// Checks that every field and button of the open dialog can be hit with a finger.
void expectTouchSized(QDialog& dialog) {
    for (QWidget* child : dialog.findChildren<QWidget*>()) {
        if (qobject_cast<QAbstractButton*>(child) || qobject_cast<QAbstractSpinBox*>(child) ||
            qobject_cast<QComboBox*>(child) || qobject_cast<QLineEdit*>(child)) {
            EXPECT_GE(child->height(), 48) << child->metaObject()->className();
        }
    }
}

TEST_F(MachineScreens, SetPresetAsksForAxisAndValueInTouchSizedDialogs) {
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    MachineSession* session = window->session();
    SoftkeyBar& bar = *window->softkeys();
    keyText(bar, "setPreset");  // brings its row on the screen
    const double machineX =
        session->status().axes[static_cast<size_t>(axisIndex(Axis::X))].machineActual;
    bool sawAxis = false;
    bool sawValue = false;
    QTimer::singleShot(0, [&] {
        auto* axisDialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(axisDialog, nullptr);
        EXPECT_EQ(axisDialog->objectName(), QStringLiteral("presetAxisPrompt"));
        expectTouchSized(*axisDialog);
        sawAxis = true;
        axisDialog->setTextValue(QStringLiteral("X"));
        QTimer::singleShot(0, [&] {
            auto* valueDialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
            ASSERT_NE(valueDialog, nullptr);
            EXPECT_EQ(valueDialog->objectName(), QStringLiteral("presetValuePrompt"));
            expectTouchSized(*valueDialog);
            sawValue = true;
            valueDialog->setDoubleValue(25.0);
            valueDialog->accept();
        });
        axisDialog->accept();
    });
    ASSERT_TRUE(bar.pressId("setPreset"));
    EXPECT_TRUE(sawAxis);
    EXPECT_TRUE(sawValue);
    // The tool stays where it is; its X now reads 25: the origin lies 25 below it.
    EXPECT_NEAR(session->presetInMachine()[Axis::X], machineX - 25.0, 1e-6);
}

TEST_F(MachineScreens, ManualSpindleStartsAtTheEnteredSpeedWithinTheMachinesMaximum) {
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    MachineSession* session = window->session();
    SoftkeyBar& bar = *window->softkeys();
    EXPECT_EQ(keyText(bar, "spindleSpeed"), QStringLiteral("S\n1000"));
    const int spindleRow = bar.currentRow();  // the row keyText left on the screen
    ASSERT_GT(spindleRow, 0);
    // The mill's spindle reaches 12000 rpm (presets/mill.toml): 20000 is cut to that.
    answerNumberDialog(20000);
    ASSERT_TRUE(bar.pressId("spindleSpeed"));
    EXPECT_DOUBLE_EQ(session->manualSpindleRpm(), 12000.0);
    EXPECT_EQ(bar.currentRow(), spindleRow);  // the new label, on the same row
    answerNumberDialog(1500);
    ASSERT_TRUE(bar.pressId("spindleSpeed"));
    EXPECT_DOUBLE_EQ(session->manualSpindleRpm(), 1500.0);
    EXPECT_EQ(keyText(bar, "spindleSpeed"), QStringLiteral("S\n1500"));

    ASSERT_TRUE(bar.pressId("spindleOn"));
    ASSERT_TRUE(processUntil([&] { return session->status().actualSpindleRpm > 1499.0; }, 5s));
    EXPECT_DOUBLE_EQ(session->status().programmedSpindleRpm, 1500.0);
    auto* status = window->positions()->findChild<QLabel*>("spindleSpeed");
    ASSERT_NE(status, nullptr);
    EXPECT_TRUE(status->text().startsWith(QStringLiteral("S 1500 ")))
        << status->text().toStdString();
    ASSERT_TRUE(bar.pressId("spindleOff"));
    EXPECT_TRUE(processUntil([&] { return session->status().actualSpindleRpm == 0.0; }, 5s));
}

// A real control stops the spindle when Spindle off is pressed while it still speeds up, and
// switches the coolant meanwhile (they were refused as "busy" until the speed was reached).
TEST_F(MachineScreens, SpindleOffAndCoolantKeysActWhileTheSpindleStillRampsUp) {
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    MachineSession* session = window->session();
    const task::MachineStatus& status = session->status();
    SoftkeyBar& bar = *window->softkeys();
    // 12000 rpm at 3000 rpm/s (presets/mill.toml): 4 s of ramp.
    keyText(bar, "spindleSpeed");
    answerNumberDialog(12000);
    ASSERT_TRUE(bar.pressId("spindleSpeed"));
    ASSERT_TRUE(bar.pressId("spindleOn"));
    ASSERT_TRUE(processUntil([&] { return status.actualSpindleRpm > 1000.0; }, 5s));
    ASSERT_TRUE(bar.pressId("coolantOn"));
    ASSERT_TRUE(processUntil([&] { return status.coolant; }, 1s));
    const double atPress = status.actualSpindleRpm;
    EXPECT_LT(atPress, 10000.0) << "the ramp is over already";
    const QSignalSpy refusals(session, &MachineSession::message);
    ASSERT_TRUE(bar.pressId("spindleOff"));
    EXPECT_EQ(refusals.count(), 0) << "Spindle off refused while the spindle ramps";
    EXPECT_TRUE(processUntil([&] { return status.programmedSpindleRpm == 0.0; }, 1s));
    // It slows down from where it was and stands. Turning the ramp round (3000 rpm/s at 60000
    // rpm/s² of jerk) adds 75 rpm; a status period or two of latency adds at most some 300.
    double fastest = 0.0;
    ASSERT_TRUE(processUntil(
        [&] {
            fastest = std::max(fastest, status.actualSpindleRpm);
            return status.actualSpindleRpm == 0.0;
        },
        6s));
    EXPECT_LT(fastest, atPress + 600.0);
    EXPECT_TRUE(status.coolant) << "Spindle off switched the coolant off";
    ASSERT_TRUE(bar.pressId("coolantOff"));
    EXPECT_TRUE(processUntil([&] { return !status.coolant; }, 1s));
}

// Runs one MDI block through the MDI dialog; `choose` fills in the dialog as the operator would.
void runMdi(MainWindow& window, const std::function<void(MdiDialog&)>& choose) {
    QTimer::singleShot(0, [choose] {
        auto* dialog = qobject_cast<MdiDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        choose(*dialog);
        dialog->okButton()->click();
    });
    ASSERT_TRUE(window.softkeys()->pressId("mdiExecute"));
    ASSERT_TRUE(processUntil([&] { return window.session()->busy(); }, 2s));
    ASSERT_TRUE(processUntil([&] { return !window.session()->busy(); }));
}

TEST_F(MachineScreens, MdiKeepsTheBlocksRunAndTheArrowKeysPickOneToRunAgain) {
    openWindow(false);  // no reference run needed before MDI
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Mdi));
    const QString first = QStringLiteral("L X+5 FMAX");
    const QString second = QStringLiteral("L X+8 FMAX");
    runMdi(*window, [&](MdiDialog& dialog) {
        EXPECT_EQ(dialog.blockField()->count(), 0);  // nothing run yet
        dialog.blockField()->setEditText(first);
    });
    EXPECT_NEAR(x(), 5.0, 1e-6);
    runMdi(*window, [&](MdiDialog& dialog) {
        EXPECT_TRUE(dialog.block().isEmpty());  // a new block starts from an empty field
        dialog.blockField()->setEditText(second);
    });
    EXPECT_NEAR(x(), 8.0, 1e-6);
    EXPECT_EQ(window->session()->mdiHistory(), QStringList({second, first}));

    // Arrow down twice: the latest block, then the one before it; it runs again.
    runMdi(*window, [&](MdiDialog& dialog) {
        QComboBox* field = dialog.blockField();
        ASSERT_EQ(field->count(), 2);
        // Field, buttons and the list's rows are finger sized.
        for (QWidget* widget :
             {static_cast<QWidget*>(field), static_cast<QWidget*>(dialog.okButton()),
              static_cast<QWidget*>(dialog.cancelButton())})
            EXPECT_GE(widget->height(), SoftkeyBar::kMinimumKeyHeight);
        EXPECT_GE(field->view()->sizeHintForRow(1), SoftkeyBar::kMinimumKeyHeight);
        QTest::keyClick(field, Qt::Key_Down);
        EXPECT_EQ(dialog.block(), second);
        QTest::keyClick(field, Qt::Key_Down);
        EXPECT_EQ(dialog.block(), first);
    });
    EXPECT_NEAR(x(), 5.0, 1e-6);
    // Run again, it moves to the top and is kept once.
    EXPECT_EQ(window->session()->mdiHistory(), QStringList({first, second}));
}

// Single block belongs to Program run: an MDI block after it runs to its end without NC start,
// and Program run single block stops after each block again afterwards.
TEST_F(MachineScreens, MdiAfterProgramRunSingleBlockRunsItsBlockToTheEnd) {
    openWindow(false);
    MachineSession* session = window->session();
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::SingleBlock));
    ASSERT_TRUE(session->singleBlock());
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Mdi));
    runMdi(*window, [](MdiDialog& dialog) { dialog.blockField()->setEditText("L X+7 FMAX"); });
    EXPECT_EQ(session->runState(), task::RunState::Finished);
    EXPECT_NEAR(x(), 7.0, 1e-6);

    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::SingleBlock));
    ASSERT_TRUE(
        session->startProgram("0 BEGIN PGM S MM\n1 L X+2 FMAX\n2 L X+4 FMAX\n"
                              "3 END PGM S MM\n",
                              "S.H"));
    ASSERT_TRUE(
        processUntil([&] { return session->status().state == task::MachineState::Stopped; }, 5s));
    EXPECT_NEAR(x(), 2.0, 1e-6);
    session->stop();
    ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
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
    // The key latches as the machine's button does: Machine on is refused until it is released.
    EXPECT_TRUE(keys->emergencyStopKey()->text().contains("Release"));
    EXPECT_TRUE(window->grab().save("emergency_stop_screen.png"));
    keys->machineOnKey()->click();
    processUntil([] { return false; }, 100ms);
    EXPECT_EQ(session->status().state, task::MachineState::EmergencyStop);
    keys->emergencyStopKey()->click();
    ASSERT_TRUE(processUntil([&] { return !session->status().emergencyStopOpen; }, 1s));
    EXPECT_FALSE(keys->emergencyStopKey()->text().contains("Release"));
    keys->machineOnKey()->click();
    ASSERT_TRUE(
        processUntil([&] { return session->status().state == task::MachineState::Idle; }, 2s));
    // Machine on again: an information, not a fault, that leaves the line by itself (the 3 s of
    // docs/hmi.md) without CE.
    MessagePanel* messages = window->messages();
    messages->clearMessages();
    keys->machineOnKey()->click();
    const QString onAlready = QStringLiteral("on already");
    EXPECT_TRUE(messages->line()->text().contains(onAlready));
    EXPECT_EQ(messages->standingCount(), 1);
    processUntil([] { return false; }, 1s);
    EXPECT_TRUE(messages->line()->text().contains(onAlready)) << "gone before it can be read";
    EXPECT_TRUE(processUntil([&] { return messages->standingCount() == 0; }, 4s));
    EXPECT_FALSE(messages->line()->text().contains(onAlready));
}

// The PGM tab's M functions and spindle speed follow the machine once no program moves it: a
// Stop turns the program's spindle and coolant off (docs/hmi.md, Stop), and the manual keys turn
// them on and off again. They showed the program's M3 M8 and its S after all of that.
TEST_F(MachineScreens, ThePgmTabFollowsTheSpindleAndCoolantAfterAProgramAndTheManualKeys) {
    std::ofstream(dir / "S.H") << "0 BEGIN PGM S MM\n"
                                  "1 TOOL CALL 0 Z S2000\n"
                                  "2 L X+0 Y+0 Z+0 R0 FMAX M3 M8\n"
                                  "3 L X+50 F100\n"
                                  "4 END PGM S MM\n";
    ASSERT_TRUE(window->openProgram(dir / "S.H"));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    auto* tabs = window->findChild<StatusTabs*>();
    auto pgm = [tabs](const char* row) { return tabs->valueOf(StatusTabs::Tab::Program, row); };
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    // Block 3 cuts (30 s at F100): the program's spindle and coolant.
    ASSERT_TRUE(processUntil([&] { return x() > 1.0 && pgm("M functions") == "M3 M8"; }));
    EXPECT_EQ(pgm("Spindle"), "S 2000 rpm");
    ASSERT_TRUE(window->softkeys()->pressId("abort"));
    ASSERT_TRUE(processUntil([&] { return !window->session()->busy(); }));
    EXPECT_TRUE(processUntil([&] { return pgm("M functions") == "M5 M9"; }, 2s))
        << pgm("M functions").toStdString();
    EXPECT_EQ(pgm("Spindle"), "S 2000 rpm");  // the S programmed stays, the spindle is off (M5)

    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    ASSERT_TRUE(window->softkeys()->pressId("spindleOn"));  // at the manual speed, 1000 rpm
    EXPECT_TRUE(processUntil([&] { return pgm("M functions") == "M3 M9"; }, 2s))
        << pgm("M functions").toStdString();
    EXPECT_EQ(pgm("Spindle"), "S 1000 rpm");
    ASSERT_TRUE(window->softkeys()->pressId("coolantOn"));
    EXPECT_TRUE(processUntil([&] { return pgm("M functions") == "M3 M8"; }, 2s))
        << pgm("M functions").toStdString();
    ASSERT_TRUE(window->softkeys()->pressId("spindleOff"));
    EXPECT_TRUE(processUntil([&] { return pgm("M functions") == "M5 M8"; }, 2s))
        << pgm("M functions").toStdString();
    // The rest of the tab is still the program's.
    EXPECT_EQ(pgm("Program"), "S.H");
}

}  // namespace
}  // namespace kerf::ui
