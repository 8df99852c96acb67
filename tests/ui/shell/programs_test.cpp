#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTextBlock>
#include <fstream>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/editor/program_checker.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/files/new_program_dialog.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
#include "ui/tables/table_editor.h"
#include "ui/tables/tnc_table_model.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

HmiContext contextIn(const fs::path& dir, const char* machineName = "mill") {
    HmiContext context;
    context.machine = *machine::loadMachine(machineName);
    context.ncRoot = dir;
    context.recoveryFolder = dir.parent_path() / (dir.filename().string() + "_recovery");
    return context;
}

std::string fileText(const fs::path& path) {
    auto bytes = readWholeFile(path);
    return bytes ? *bytes : std::string("<missing>");
}

MainWindow::Prompts answeringNewProgram(const NewProgramSpec& spec) {
    MainWindow::Prompts prompts;
    prompts.newProgram = [spec] { return std::optional<NewProgramSpec>(spec); };
    return prompts;
}

void edit(MainWindow& window) {
    QTextCursor cursor(window.program()->editor()->document()->findBlockByNumber(1));
    cursor.movePosition(QTextCursor::EndOfBlock);
    cursor.insertText(" M3");
}

TEST(NewProgram, TheMillWritesBeginPgmTheBlankAndEndPgmAndOpensIt) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_new_program");
    MainWindow window(contextIn(dir));
    NewProgramSpec spec;
    spec.name = "PLATE";
    spec.blankMin = {-10.0, 0.0, -25.5};
    spec.blankMax = {120.0, 80.0, 0.0};
    window.setPrompts(answeringNewProgram(spec));
    window.showFiles();
    ASSERT_TRUE(window.softkeys()->pressId("fileNewProgram"));
    EXPECT_EQ(fileText(dir / "PLATE.H"),
              "0 BEGIN PGM PLATE MM\n"
              "1 BLK FORM 0.1 Z X-10 Y+0 Z-25.5\n"
              "2 BLK FORM 0.2 X+120 Y+80 Z+0\n"
              "3 END PGM PLATE MM\n");
    EXPECT_EQ(window.program()->path(), dir / "PLATE.H");
    EXPECT_EQ(window.modes().programmingMode(), task::ProgrammingMode::Programming);
    // The cursor waits at the end of the second BLK FORM, where the first block follows (it
    // stood before BEGIN PGM: a block typed went into the header line).
    const QTextCursor cursor = window.program()->editor()->textCursor();
    EXPECT_EQ(cursor.blockNumber(), 2);
    EXPECT_TRUE(cursor.atBlockEnd());
    // The new program passes the check.
    window.program()->checkNow();
    QSignalSpy checked(window.program(), &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(checked.wait(10000));
    EXPECT_FALSE(hasErrors(window.program()->diagnostics()));
    // A second program of the same name is refused; the first stays as it was.
    const std::string before = fileText(dir / "PLATE.H");
    spec.inch = true;
    window.setPrompts(answeringNewProgram(spec));
    const int messages = window.messages()->messageCount();
    EXPECT_FALSE(window.newProgram());
    EXPECT_EQ(fileText(dir / "PLATE.H"), before);
    EXPECT_EQ(window.messages()->messageCount(), messages + 1);
}

// A name ending in .I makes a TNC ISO program (docs/tnciso.md): the same blank as G30/G31, the
// header and the end block; the editor treats it as ISO and it checks clean.
TEST(NewProgram, AnIsoNameWritesTheIsoHeaderBlankAndEndBlock) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_new_program_iso");
    MainWindow window(contextIn(dir));
    NewProgramSpec spec;
    spec.name = "PLATE.I";
    spec.blankMin = {-10.0, 0.0, -25.5};
    spec.blankMax = {120.0, 80.0, 0.0};
    window.setPrompts(answeringNewProgram(spec));
    ASSERT_TRUE(window.newProgram());
    EXPECT_EQ(fileText(dir / "PLATE.I"),
              "%PLATE G71 *\n"
              "N10 G30 G17 X-10 Y+0 Z-25.5 *\n"
              "N20 G31 G90 X+120 Y+80 Z+0 *\n"
              "N99999999 %PLATE G71 *\n");
    EXPECT_EQ(window.program()->editor()->dialect(), program::Dialect::TncIso);
    window.program()->checkNow();
    QSignalSpy checked(window.program(), &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(checked.wait(10000));
    EXPECT_FALSE(hasErrors(window.program()->diagnostics()));
}

TEST(NewProgram, InchAndALatheProgramWithItsPercentHeader) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_new_program_lathe");
    MainWindow window(contextIn(dir, "lathe"));
    NewProgramSpec spec;
    spec.name = "SHAFT";
    spec.inch = true;
    window.setPrompts(answeringNewProgram(spec));
    ASSERT_TRUE(window.newProgram());
    EXPECT_EQ(fileText(dir / "SHAFT.PIM"), "%SHAFT,MX,\nN10 G70\nN20 M30\n");
    // The cursor after G70, before M30.
    EXPECT_EQ(window.program()->editor()->textCursor().blockNumber(), 1);
    EXPECT_TRUE(window.program()->editor()->textCursor().atBlockEnd());
    EXPECT_EQ(window.program()->editor()->dialect(), program::Dialect::Fagor);
    // The name typed as the header writes it, with its %: the file and the header have one %.
    spec.name = "%PART";
    spec.inch = false;
    window.setPrompts(answeringNewProgram(spec));
    ASSERT_TRUE(window.newProgram());
    EXPECT_EQ(fileText(dir / "PART.PIM"), "%PART,MX,\nN10 G71\nN20 M30\n");
    EXPECT_FALSE(fs::exists(dir / "%PART.PIM"));
}

TEST(NewProgram, TheDialogAsksForTheBlankOnAMillAndRefusesAnEmptyName) {
    test::testApp();
    const auto mill = *machine::loadMachine("mill");
    NewProgramDialog dialog(mill);
    ASSERT_NE(dialog.blankField(0), nullptr);
    dialog.accept();  // no name yet
    EXPECT_FALSE(dialog.problem()->isHidden());
    EXPECT_NE(dialog.result(), QDialog::Accepted);
    dialog.nameField()->setText(QStringLiteral("A1"));
    dialog.blankField(2)->setValue(5.0);  // MIN Z above MAX Z 0
    dialog.accept();
    EXPECT_NE(dialog.result(), QDialog::Accepted);
    dialog.blankField(2)->setValue(-5.0);
    dialog.unitField()->setCurrentIndex(1);
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(dialog.spec().name, "A1");
    EXPECT_TRUE(dialog.spec().inch);
    EXPECT_DOUBLE_EQ(dialog.spec().blankMin[2], -5.0);
    NewProgramDialog lathe(*machine::loadMachine("lathe"));
    EXPECT_EQ(lathe.blankField(0), nullptr);
}

TEST(UnsavedEdits, OpeningAnotherProgramAsksAndFollowsTheAnswer) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_unsaved_open");
    const std::string a = "0 BEGIN PGM A MM\n1 L Z+50 R0 FMAX\n2 END PGM A MM\n";
    std::ofstream(dir / "A.H") << a;
    std::ofstream(dir / "B.H") << "0 BEGIN PGM B MM\n1 END PGM B MM\n";
    MainWindow window(contextIn(dir));
    QStringList asked;
    MainWindow::UnsavedChoice answer = MainWindow::UnsavedChoice::Cancel;
    MainWindow::Prompts prompts;
    prompts.unsavedEdits = [&](const QString& program) {
        asked << program;
        return answer;
    };
    window.setPrompts(prompts);
    ASSERT_TRUE(window.openProgram(dir / "A.H"));
    EXPECT_TRUE(asked.isEmpty());  // nothing was edited
    edit(window);
    // Cancel: A stays with its edits.
    EXPECT_FALSE(window.openProgram(dir / "B.H"));
    ASSERT_EQ(asked, QStringList{QStringLiteral("A.H")});
    EXPECT_EQ(window.program()->path(), dir / "A.H");
    EXPECT_TRUE(window.program()->modified());
    // Save: A is written, then B opens.
    answer = MainWindow::UnsavedChoice::Save;
    ASSERT_TRUE(window.openProgram(dir / "B.H"));
    EXPECT_EQ(window.program()->path(), dir / "B.H");
    EXPECT_EQ(fileText(dir / "A.H"), "0 BEGIN PGM A MM\n1 L Z+50 R0 FMAX M3\n2 END PGM A MM\n");
    // Discard: the edit of B is lost, the file stays.
    edit(window);
    answer = MainWindow::UnsavedChoice::Discard;
    ASSERT_TRUE(window.openProgram(dir / "A.H"));
    EXPECT_EQ(fileText(dir / "B.H"), "0 BEGIN PGM B MM\n1 END PGM B MM\n");
    EXPECT_EQ(asked.size(), 3);
}

TEST(UnsavedEdits, ClosingAsksAndCancelKeepsTheWindowOpen) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_unsaved_close");
    std::ofstream(dir / "A.H") << "0 BEGIN PGM A MM\n1 L Z+50 R0 FMAX\n2 END PGM A MM\n";
    MainWindow window(contextIn(dir));
    int asked = 0;
    MainWindow::UnsavedChoice answer = MainWindow::UnsavedChoice::Cancel;
    MainWindow::Prompts prompts;
    prompts.unsavedEdits = [&](const QString&) {
        ++asked;
        return answer;
    };
    window.setPrompts(prompts);
    ASSERT_TRUE(window.openProgram(dir / "A.H"));
    window.show();
    edit(window);
    EXPECT_FALSE(window.close());
    EXPECT_TRUE(window.isVisible());
    EXPECT_EQ(asked, 1);
    answer = MainWindow::UnsavedChoice::Save;
    EXPECT_TRUE(window.close());
    EXPECT_EQ(fileText(dir / "A.H"), "0 BEGIN PGM A MM\n1 L Z+50 R0 FMAX M3\n2 END PGM A MM\n");
}

TEST(UnsavedEdits, AnotherTableOrQuittingAsksAboutAnEditedTable) {
    // An edited cell of TOOL.T was lost when another table opened or the window closed.
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_unsaved_table");
    MainWindow window(contextIn(dir));
    QStringList asked;
    MainWindow::UnsavedChoice answer = MainWindow::UnsavedChoice::Cancel;
    MainWindow::Prompts prompts;
    prompts.unsavedEdits = [&](const QString& name) {
        asked << name;
        return answer;
    };
    window.setPrompts(prompts);
    ASSERT_TRUE(window.openFile(dir / "TOOL.T"));  // the standard table of a fresh NC root
    TncTableModel* model = window.tables()->model();
    ASSERT_NE(model, nullptr);
    int lengthColumn = -1;
    for (int c = 0; c < model->columnCount(); ++c) {
        const QString header = model->headerData(c, Qt::Horizontal, Qt::DisplayRole).toString();
        if (header == QStringLiteral("L") || header.startsWith(QStringLiteral("L\n"))) {
            lengthColumn = c;
        }
    }
    ASSERT_GE(lengthColumn, 0);
    ASSERT_GT(model->rowCount(), 0);
    ASSERT_TRUE(
        model->setData(model->index(0, lengthColumn), QStringLiteral("123.456"), Qt::EditRole));
    ASSERT_TRUE(window.tables()->modified());
    // Cancel: the edited table stays.
    EXPECT_FALSE(window.openFile(dir / "PRESET.PR"));
    EXPECT_EQ(asked, QStringList{QStringLiteral("TOOL.T")});
    EXPECT_EQ(window.tables()->path(), dir / "TOOL.T");
    EXPECT_TRUE(window.tables()->modified());
    // Quitting asks too; Save writes the edit before the window closes.
    window.show();
    EXPECT_FALSE(window.close());
    answer = MainWindow::UnsavedChoice::Save;
    EXPECT_TRUE(window.close());
    EXPECT_EQ(asked.size(), 3);
    EXPECT_NE(fileText(dir / "TOOL.T").find("123.456"), std::string::npos);
}

}  // namespace
}  // namespace kerf::ui
