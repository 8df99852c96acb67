#include "ui/shell/main_window.h"

#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTextBlock>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/files/file_manager.h"
#include "ui/shell/machine_keys.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/ui_language.h"
#include "ui/shell/workspace.h"
#include "ui/status/status_tabs.h"
#include "ui/tables/table_editor.h"

namespace kerf::ui {
namespace {

using task::MachineMode;
using task::ProgrammingMode;

HmiContext contextIn(const std::filesystem::path& dir) {
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    return context;
}

QString labelText(const MainWindow& window, const char* name) {
    return window.findChild<QLabel*>(name)->text();
}

TEST(MainWindow, SoftkeysAreTouchSizedAtBothPanelSizes) {
    test::testApp();
    MainWindow window(contextIn(kerf::test::uniqueTempDir("hmi_window_sizes")));
    for (const QSize size : {QSize(1280, 800), QSize(1920, 1080)}) {
        window.resize(size);
        window.show();
        QCoreApplication::processEvents();
        for (int i = 0; i < SoftkeyBar::kKeys; ++i)
            EXPECT_GE(window.softkeys()->keyButton(i)->height(), 48);
        for (QPushButton* key : window.machineKeys()->findChildren<QPushButton*>())
            EXPECT_GE(key->height(), 48);
        EXPECT_GE(window.messages()->line()->height(), 48);
    }
    EXPECT_TRUE(
        window.windowTitle().contains(QString::fromStdString(machine::loadMachine("mill")->name)));
}

// On the lathe the modes have the 8035's names (OPMODE, spec part 2 §5.15), in every language.
TEST(MainWindow, LatheNamesTheModesAsTheFagorDoes) {
    test::testApp();
    HmiContext context = contextIn(kerf::test::uniqueTempDir("hmi_window_fagor_modes"));
    context.machine = *machine::loadMachine("lathe");
    MainWindow window(std::move(context));
    window.show();
    const auto keyText = [&window](MachineMode mode) {
        return window.machineKeys()->machineKey(mode)->text().replace('\n', ' ');
    };
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("JOG"));
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Editing"));
    EXPECT_EQ(keyText(MachineMode::Manual), QStringLiteral("JOG"));
    EXPECT_EQ(keyText(MachineMode::Handwheel), QStringLiteral("Electronic handwheel"));
    EXPECT_EQ(keyText(MachineMode::Mdi), QStringLiteral("MDI"));
    EXPECT_EQ(keyText(MachineMode::SingleBlock), QStringLiteral("Single-block execution"));
    EXPECT_EQ(keyText(MachineMode::FullSequence), QStringLiteral("Automatic execution"));
    EXPECT_EQ(window.machineKeys()->programmingKey(ProgrammingMode::TestRun)->text(),
              QStringLiteral("Simulation"));
    ASSERT_TRUE(window.setLanguage(QStringLiteral("es")));
    QCoreApplication::processEvents();  // the widgets retranslate on the posted LanguageChange
    EXPECT_EQ(keyText(MachineMode::FullSequence), QStringLiteral("Ejecución automática"));
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Edición"));
    ASSERT_TRUE(window.setLanguage(QStringLiteral("en")));
}

// The lathe's parameters are FAGOR's P also on a screen that has not run a program yet: from
// Simulation to Automatic execution before any run the tab said QPARA (the TNC's name).
TEST(MainWindow, LatheParameterTabSaysPBeforeAnyRun) {
    test::testApp();
    HmiContext context = contextIn(kerf::test::uniqueTempDir("hmi_window_fagor_para"));
    context.machine = *machine::loadMachine("lathe");
    MainWindow window(std::move(context));
    window.show();
    auto* tabs = window.findChild<StatusTabs*>();
    ASSERT_NE(tabs, nullptr);
    const auto parameterTab = [tabs] {
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->tabText(i).endsWith(QStringLiteral("PARA"))) return tabs->tabText(i);
        return QString();
    };
    EXPECT_EQ(parameterTab(), QStringLiteral("PPARA"));
    QTest::mouseClick(window.machineKeys()->programmingKey(ProgrammingMode::TestRun),
                      Qt::LeftButton);
    EXPECT_EQ(parameterTab(), QStringLiteral("PPARA"));
    QTest::mouseClick(window.machineKeys()->machineKey(MachineMode::FullSequence), Qt::LeftButton);
    EXPECT_EQ(parameterTab(), QStringLiteral("PPARA"));
    QTest::mouseClick(window.machineKeys()->programmingKey(ProgrammingMode::TestRun),
                      Qt::LeftButton);
    EXPECT_EQ(parameterTab(), QStringLiteral("PPARA"));
}

// With no program open the lathe's programming rows are FAGOR's: the canned cycles, not the
// TNC's CYCL DEF, TOOL CALL and path keys.
TEST(MainWindow, TheLatheProgramsInFagorBeforeAProgramIsOpen) {
    test::testApp();
    HmiContext context = contextIn(kerf::test::uniqueTempDir("hmi_window_fagor_rows"));
    context.machine = *machine::loadMachine("lathe");
    MainWindow window(std::move(context));
    window.show();
    window.modes().requestProgrammingMode(ProgrammingMode::Programming);
    EXPECT_EQ(window.program()->editor()->dialect(), program::Dialect::Fagor);
    EXPECT_FALSE(window.softkeys()->pressId(QStringLiteral("cyclDef")));
    EXPECT_FALSE(window.softkeys()->pressId(QStringLiteral("pathL")));
    EXPECT_TRUE(window.softkeys()->pressId(QStringLiteral("fagorCycles")));
}

TEST(MainWindow, HeaderFollowsModeKeys) {
    test::testApp();
    MainWindow window(contextIn(kerf::test::uniqueTempDir("hmi_window_modes")));
    window.show();
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Manual operation"));
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Programming"));
    QTest::mouseClick(window.machineKeys()->machineKey(MachineMode::Mdi), Qt::LeftButton);
    EXPECT_EQ(window.modes().machineMode(), MachineMode::Mdi);
    EXPECT_EQ(labelText(window, "machineMode"),
              QStringLiteral("Positioning with manual data input"));
    EXPECT_TRUE(window.machineKeys()->machineKey(MachineMode::Mdi)->isChecked());
    EXPECT_FALSE(window.machineKeys()->machineKey(MachineMode::Manual)->isChecked());
    QTest::mouseClick(window.machineKeys()->programmingKey(ProgrammingMode::TestRun),
                      Qt::LeftButton);
    EXPECT_EQ(window.modes().programmingMode(), ProgrammingMode::TestRun);
    EXPECT_EQ(window.modes().screen(), ScreenMode::Programming);
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Test run"));
    EXPECT_EQ(labelText(window, "machineMode"),
              QStringLiteral("Positioning with manual data input"));
}

TEST(MainWindow, ProgrammingStationOffersOnlyTheProgrammingModes) {
    test::testApp();
    HmiContext context = contextIn(kerf::test::uniqueTempDir("hmi_window_station"));
    context.programmingStation = true;
    MainWindow window(std::move(context));
    window.show();
    EXPECT_EQ(window.modes().screen(), ScreenMode::Programming);
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Programming station"));
    for (MachineMode mode : {MachineMode::Manual, MachineMode::Handwheel, MachineMode::Mdi,
                             MachineMode::SingleBlock, MachineMode::FullSequence}) {
        EXPECT_FALSE(window.machineKeys()->machineKey(mode)->isEnabled());
        EXPECT_FALSE(window.machineKeys()->machineKey(mode)->isChecked());
    }
    // Asked anyway (e.g. by a shortcut): refused with a message, the screen stays.
    EXPECT_FALSE(window.modes().requestMachineMode(MachineMode::FullSequence));
    EXPECT_EQ(window.modes().screen(), ScreenMode::Programming);
    ASSERT_EQ(window.messages()->messageCount(), 1);
    QTest::mouseClick(window.machineKeys()->programmingKey(ProgrammingMode::TestRun),
                      Qt::LeftButton);
    EXPECT_EQ(window.modes().programmingMode(), ProgrammingMode::TestRun);
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Test run"));
}

TEST(MainWindow, ModeChangeWhileMovingIsRefusedWithAMessage) {
    test::testApp();
    MainWindow window(contextIn(kerf::test::uniqueTempDir("hmi_window_refuse")));
    bool moving = false;
    window.modes().setMovingQuery([&moving] { return moving; });
    ASSERT_TRUE(window.modes().requestMachineMode(MachineMode::FullSequence));
    moving = true;
    QTest::mouseClick(window.machineKeys()->machineKey(MachineMode::Manual), Qt::LeftButton);
    EXPECT_EQ(window.modes().machineMode(), MachineMode::FullSequence);
    EXPECT_FALSE(window.machineKeys()->machineKey(MachineMode::Manual)->isChecked());
    EXPECT_TRUE(window.machineKeys()->machineKey(MachineMode::FullSequence)->isChecked());
    ASSERT_EQ(window.messages()->messageCount(), 1);
    EXPECT_EQ(window.messages()->list()->topLevelItem(0)->text(0), QStringLiteral("Error"));
}

TEST(MainWindow, SoftkeyRowsFollowTheScreenAndFunctionKeys) {
    test::testApp();
    MainWindow window(contextIn(kerf::test::uniqueTempDir("hmi_window_softkeys")));
    window.show();
    QApplication::setActiveWindow(&window);
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    EXPECT_EQ(window.softkeys()->keyButton(0)->objectName(), QStringLiteral("softkey1"));
    const QString manualFirstKey = window.softkeys()->keyButton(0)->text();
    window.modes().requestProgrammingMode(ProgrammingMode::Programming);
    EXPECT_NE(window.softkeys()->keyButton(0)->text(), manualFirstKey);
    // Editing, the common row, then CYCL DEF / path functions (two rows).
    EXPECT_EQ(window.softkeys()->rowCount(), 4);
    // F9 pages to the second row, whose first key (F1) changes the layout.
    QTest::keyClick(&window, Qt::Key_F9);
    EXPECT_EQ(window.softkeys()->currentRow(), 1);
    EXPECT_EQ(window.workspace()->layoutKind(), WorkspaceLayout::Program);
    QTest::keyClick(&window, Qt::Key_F1);
    EXPECT_EQ(window.workspace()->layoutKind(), WorkspaceLayout::ProgramGraphics);
    EXPECT_TRUE(window.findChild<QWidget*>("graphicsPanel")->isVisible());
    EXPECT_FALSE(window.findChild<QWidget*>("statusPanel")->isVisible());
    ASSERT_TRUE(window.softkeys()->pressId("layout"));
    EXPECT_EQ(window.workspace()->layoutKind(), WorkspaceLayout::ProgramStatus);
    EXPECT_TRUE(window.findChild<QWidget*>("statusPanel")->isVisible());
    EXPECT_FALSE(window.findChild<QWidget*>("graphicsPanel")->isVisible());
    ASSERT_TRUE(window.softkeys()->pressId("layout"));
    EXPECT_TRUE(window.findChild<QWidget*>("positionsPanel")->isVisible());
    EXPECT_FALSE(window.findChild<QWidget*>("programPanel")->isVisible());
}

TEST(MainWindow, ClickingADiagnosticJumpsToItsLine) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_window_jump");
    ASSERT_FALSE(writeFileAtomically(dir / "J.H",
                                     "0 BEGIN PGM J MM\n1 L Z+50 R0 FMAX\n2 L X+0 R0 FMAX\n"
                                     "3 L Y+0 R0 FMAX\n4 BOGUS WORD\n5 END PGM J MM\n")
                     .has_value());
    MainWindow window(contextIn(dir));
    window.show();
    QSignalSpy checked(window.program(), &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(window.openProgram(dir / "J.H"));
    ASSERT_TRUE(checked.wait(10000));
    QTreeWidget* list = window.messages()->list();
    int row = -1;
    for (int i = 0; i < list->topLevelItemCount(); ++i) {
        // Named by its block number: block 4 is on line 5.
        if (list->topLevelItem(i)->text(2) == QStringLiteral("4")) row = i;
    }
    ASSERT_GE(row, 0) << "no message for block 4";
    EXPECT_EQ(window.program()->editor()->currentLine(), 1);
    // The message line opens the list; a click on the message moves the editor to line 5.
    QTest::mouseClick(window.messages()->line(), Qt::LeftButton);
    ASSERT_TRUE(list->isVisible());
    const QRect rect = list->visualItemRect(list->topLevelItem(row));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, rect.center());
    EXPECT_EQ(window.program()->editor()->currentLine(), 5);
    EXPECT_EQ(window.program()->editor()->textCursor().block().text(),
              QStringLiteral("4 BOGUS WORD"));
}

TEST(MainWindow, MessagesAreNewestFirstAndANewErrorIsNotHiddenByAnOldOne) {
    test::testApp();
    MainWindow window(contextIn(kerf::test::uniqueTempDir("hmi_message_order")));
    MessagePanel* messages = window.messages();
    messages->clearMessages();
    messages->addMessage(Severity::Error, QStringLiteral("old error"), 0);
    messages->addMessage(Severity::Warning, QStringLiteral("a warning"), 0);
    messages->addMessage(Severity::Error, QStringLiteral("new error"), 0);
    EXPECT_EQ(messages->list()->topLevelItem(0)->text(1), QStringLiteral("new error"));
    EXPECT_EQ(messages->list()->topLevelItem(2)->text(1), QStringLiteral("old error"));
    EXPECT_TRUE(messages->line()->text().contains(QStringLiteral("new error")))
        << messages->line()->text().toStdString();
    // The latest 200 run messages are kept, the check's findings stay below them.
    messages->setCheckDiagnostics({Diagnostic::make(Severity::Warning, "t", "P.H", 2, 1, "found")});
    for (int i = 0; i < 250; ++i)
        messages->addMessage(Severity::Note, QStringLiteral("note %1").arg(i), 0);
    EXPECT_EQ(messages->messageCount(), 201);
    EXPECT_EQ(messages->list()->topLevelItem(0)->text(1), QStringLiteral("note 249"));
    EXPECT_EQ(messages->list()->topLevelItem(199)->text(1), QStringLiteral("note 50"));
    EXPECT_EQ(messages->list()->topLevelItem(200)->text(1), QStringLiteral("found"));
}

TEST(MainWindow, FilesAndTablesArePagesWithTheirOwnSoftkeys) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_window_pages");
    ASSERT_FALSE(
        writeFileAtomically(dir / "P.H", "0 BEGIN PGM P MM\n1 END PGM P MM\n").has_value());
    MainWindow window(contextIn(dir));
    window.show();
    ASSERT_TRUE(window.softkeys()->pressId("files"));
    EXPECT_EQ(window.workspace()->currentPage(), window.files());
    EXPECT_EQ(window.softkeys()->keyButton(SoftkeyBar::kKeys - 1)->text(), QStringLiteral("Back"));
    // Opening a program from the file manager brings it into the editor, in programming mode.
    ASSERT_TRUE(window.files()->selectPath(dir / "P.H"));
    ASSERT_TRUE(window.softkeys()->pressId("fileOpen"));
    EXPECT_EQ(window.program()->path(), dir / "P.H");
    EXPECT_EQ(window.modes().screen(), ScreenMode::Programming);
    EXPECT_NE(window.workspace()->currentPage(), window.files());
    // The tool table key creates the standard TOOL.T in a fresh NC root and opens it.
    ASSERT_TRUE(window.softkeys()->pressId("toolTable"));
    EXPECT_EQ(window.workspace()->currentPage(), window.tables());
    EXPECT_TRUE(std::filesystem::exists(dir / "TOOL.T"));
    ASSERT_TRUE(window.softkeys()->pressId("back"));
    EXPECT_NE(window.workspace()->currentPage(), window.tables());
}

TEST(MainWindow, ClosingAsksAndDiscardedEditsLeaveNoRecoveryCopy) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_window_close");
    ASSERT_FALSE(
        writeFileAtomically(dir / "C.H", "0 BEGIN PGM C MM\n1 END PGM C MM\n").has_value());
    int asked = 0;
    {
        MainWindow window(contextIn(dir));
        MainWindow::Prompts prompts;
        prompts.unsavedEdits = [&asked](const QString&) {
            ++asked;
            return MainWindow::UnsavedChoice::Discard;
        };
        window.setPrompts(prompts);
        window.show();
        ASSERT_TRUE(window.openProgram(dir / "C.H"));
        window.program()->editor()->moveCursor(QTextCursor::End);
        window.program()->editor()->insertPlainText("; note");
        window.program()->autosave();  // as the timer would have done meanwhile
        EXPECT_TRUE(window.close());
    }
    EXPECT_EQ(asked, 1);
    MainWindow again(contextIn(dir));
    ASSERT_TRUE(again.openProgram(dir / "C.H"));
    EXPECT_FALSE(again.program()->recoveryAvailable());
    EXPECT_EQ(again.program()->editor()->toPlainText(),
              QStringLiteral("0 BEGIN PGM C MM\n1 END PGM C MM\n"));
}

TEST(MainWindow, LanguageSwitchesAtRunTime) {
    test::testApp();
    MainWindow window(contextIn(kerf::test::uniqueTempDir("hmi_window_language")));
    window.show();
    EXPECT_EQ(availableLanguages(), (QStringList{"en", "de", "es", "pl", "pt"}));
    window.modes().requestProgrammingMode(ProgrammingMode::Programming);
    ASSERT_TRUE(window.setLanguage("pt"));
    QCoreApplication::processEvents();  // LanguageChange is posted to each window
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Funcionamento manual"));
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Programa\u00e7\u00e3o"));
    EXPECT_EQ(window.softkeys()->keyButton(0)->text(), QStringLiteral("Guardar"));
    EXPECT_EQ(window.messages()->line()->text(), QStringLiteral("Sem mensagens"));
    EXPECT_EQ(window.findChild<QLabel*>("programTitle")->text(), QStringLiteral("Nenhum programa"));
    ASSERT_TRUE(window.setLanguage("pl"));
    QCoreApplication::processEvents();
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Obs\u0142uga r\u0119czna"));
    EXPECT_EQ(window.softkeys()->keyButton(0)->text(), QStringLiteral("Zapisz"));
    EXPECT_FALSE(window.setLanguage("xx"));
    EXPECT_EQ(currentLanguage(), QStringLiteral("pl"));
    ASSERT_TRUE(window.setLanguage("en"));
    QCoreApplication::processEvents();
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Manual operation"));
    EXPECT_EQ(window.softkeys()->keyButton(0)->text(), QStringLiteral("Save"));
}

}  // namespace
}  // namespace kerf::ui
