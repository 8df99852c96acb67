// SEL PGM and CALL PGM's "Select file" (docs/hmi.md, "Special functions"): the file list shows the
// NC root's programs and nothing above the root, and the chosen program is written as the TNC
// writes it — by its name in the calling program's folder, by `TNC:\...` elsewhere — in a
// conversational and in a TNC ISO program; what is written passes the running check.
#include <QApplication>
#include <QFileSystemModel>
#include <QLineEdit>
#include <QPushButton>
#include <QTest>
#include <QTextBlock>
#include <QTimer>
#include <QTreeView>
#include <functional>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "core/task/dry_run.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/cycles/program_file_dialog.h"
#include "ui/cycles/program_reference.h"
#include "ui/cycles/programming_softkeys.h"
#include "ui/cycles/special_function_dialog.h"
#include "ui/editor/program_editor.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

// root/PARTS/MAIN.H calls; root/PARTS/SUB.H and root/PARTS/DEEP/X.I lie beside and below it,
// root/OTHER/Y.H elsewhere in the root; root/OUT.H is a link to a program outside the root.
struct NcTree {
    fs::path root;
    fs::path outside;
};

NcTree makeTree(const std::string& name) {
    const fs::path base = kerf::test::uniqueTempDir(name);
    NcTree tree{base / "nc", base / "outside"};
    for (const fs::path& folder : {tree.root / "PARTS" / "DEEP", tree.root / "OTHER", tree.outside})
        fs::create_directories(folder);
    const auto write = [](const fs::path& path, const std::string& text) {
        EXPECT_FALSE(writeFileAtomically(path, text).has_value()) << path;
    };
    write(tree.root / "PARTS" / "SUB.H", "0 BEGIN PGM SUB MM\n1 END PGM SUB MM\n");
    write(tree.root / "PARTS" / "DEEP" / "X.I", "%X G71 *\nN99999999 %X G71 *\n");
    write(tree.root / "OTHER" / "Y.H", "0 BEGIN PGM Y MM\n1 END PGM Y MM\n");
    write(tree.outside / "Z.H", "0 BEGIN PGM Z MM\n1 END PGM Z MM\n");
    fs::create_symlink(tree.outside / "Z.H", tree.root / "OUT.H");
    return tree;
}

TEST(ProgramReference, IsTheNameInTheCallersFolderElseTheFullTncPath) {
    test::testApp();
    const NcTree tree = makeTree("program_reference");
    const ProgramPlace place{tree.root, tree.root / "PARTS"};
    const auto name = [&](const fs::path& chosen) {
        const ProgramReference reference = programReference(chosen, place);
        return reference.refusal.isEmpty() ? reference.name.toStdString()
                                           : "!" + reference.refusal.toStdString();
    };
    EXPECT_EQ(name(tree.root / "PARTS" / "SUB.H"), "SUB.H");
    EXPECT_EQ(name(tree.root / "PARTS" / "DEEP" / "X.I"), "DEEP\\X.I");
    EXPECT_EQ(name(tree.root / "OTHER" / "Y.H"), "TNC:\\OTHER\\Y.H");
    // An unsaved program counts from the NC root, as the interpreter resolves its calls.
    EXPECT_EQ(programReference(tree.root / "OTHER" / "Y.H", {tree.root, {}}).name.toStdString(),
              "OTHER\\Y.H");
    // Outside the root: directly, through "..", through a link; a folder is no program.
    EXPECT_EQ(name(tree.outside / "Z.H"),
              "!'" + (tree.outside / "Z.H").string() + "' is outside the NC root");
    EXPECT_EQ(name(tree.root / ".." / "outside" / "Z.H").front(), '!');
    EXPECT_EQ(name(tree.root / "OUT.H"),
              "!'" + (tree.root / "OUT.H").string() + "' is outside the NC root");
    EXPECT_EQ(name(tree.root / "OTHER"),
              "!'" + (tree.root / "OTHER").string() + "' is not a regular file");
}

// Schedules `fill` for the modal dialog of type Dialog once the event loop runs it.
template <typename Dialog>
void answerNextDialog(std::function<void(Dialog&)> fill) {
    QTimer::singleShot(0, [fill] {
        auto* dialog = qobject_cast<Dialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        fill(*dialog);
    });
}

// In the file list: waits until the tree shows `file`, touches it and OK.
void chooseInList(ProgramFileDialog& files, const fs::path& root, const fs::path& file) {
    // Nothing above the NC root: the tree's top is the root.
    EXPECT_EQ(files.model()->filePath(files.view()->rootIndex()).toStdString(), root.string());
    ASSERT_TRUE(QTest::qWaitFor([&] { return files.selectPath(file); }, 5000)) << file;
    const QModelIndex index = files.view()->currentIndex();
    files.view()->scrollTo(index);
    EXPECT_GE(files.view()->visualRect(index).height(), 48);  // touch sized rows
    QTest::mouseClick(files.view()->viewport(), Qt::LeftButton, {},
                      files.view()->visualRect(index).center());
    QPushButton* ok = nullptr;
    for (QPushButton* button : files.findChildren<QPushButton*>())
        if (button->text() == "OK") ok = button;
    ASSERT_NE(ok, nullptr);
    EXPECT_GE(ok->height(), 48);
    QTest::mouseClick(ok, Qt::LeftButton);
}

std::function<void()> findKey(const std::vector<SoftkeyRow>& rows, const QString& id) {
    for (const SoftkeyRow& row : rows)
        for (const Softkey& key : row)
            if (key.id == id) return key.action;
    return {};
}

// SPEC FCT -> CALL PGM (and SEL PGM) -> Select file: the program chosen in the list is written
// into the block as the TNC writes it, and the program then runs through its calls.
TEST(ProgramFile, SelectFileWritesTheChosenProgramAsTheTncWritesIt) {
    test::testApp();
    const NcTree tree = makeTree("program_file_select");
    const auto mill = machine::loadMachine("mill");
    ASSERT_TRUE(mill.ok());
    for (const auto dialect : {program::Dialect::Klartext, program::Dialect::TncIso}) {
        const bool iso = dialect == program::Dialect::TncIso;
        ProgramEditor editor;
        editor.setDialect(dialect);
        editor.setPlainText(iso ? "%MAIN G71 *\nN10 G00 G40 G90 Z+100 *\nN99999999 %MAIN G71 *"
                                : "0 BEGIN PGM MAIN MM\n1 L Z+100 R0 FMAX\n2 END PGM MAIN MM");
        editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(1)));
        std::vector<SoftkeyRow> shown;
        SoftkeyPaging paging{[&shown](std::vector<SoftkeyRow> rows) { shown = std::move(rows); },
                             [] {},
                             [&] {
                                 return ProgramPlace{tree.root, tree.root / "PARTS"};
                             }};
        const std::vector<SoftkeyRow> entry = programmingEntryRows(&editor, nullptr, paging);
        findKey(entry, "specFct")();
        // Each key and the file the operator picks for it.
        const std::vector<std::pair<QString, fs::path>> picks = {
            {"selPgm", tree.root / "PARTS" / (iso ? "DEEP/X.I" : "SUB.H")},
            {"callPgm", tree.root / "OTHER" / "Y.H"},
        };
        const std::vector<SoftkeyRow> special = shown;
        for (const auto& [key, file] : picks) {
            answerNextDialog<SpecialFunctionDialog>([&](SpecialFunctionDialog& dialog) {
                QPushButton* select = dialog.selectFileButton();
                ASSERT_NE(select, nullptr);
                EXPECT_GE(select->height(), 48);
                answerNextDialog<ProgramFileDialog>(
                    [&](ProgramFileDialog& files) { chooseInList(files, tree.root, file); });
                QTest::mouseClick(select, Qt::LeftButton);
                EXPECT_TRUE(dialog.message().isEmpty()) << dialog.message().toStdString();
                dialog.accept();
            });
            findKey(special, key)();
        }
        const std::string text = editor.toPlainText().toStdString();
        EXPECT_EQ(text, iso ? "%MAIN G71 *\nN10 G00 G40 G90 Z+100 *\nN11 SEL PGM \"DEEP\\X.I\" *\n"
                              "N12 %TNC:\\OTHER\\Y.H *\nN99999999 %MAIN G71 *"
                            : "0 BEGIN PGM MAIN MM\n1 L Z+100 R0 FMAX\n2 SEL PGM \"SUB.H\"\n"
                              "3 CALL PGM TNC:\\OTHER\\Y.H\n4 END PGM MAIN MM");
        // The calls reach their programs: a missing one would be the check's error.
        task::ProgramRequest request;
        request.path = tree.root / "PARTS" / (iso ? "MAIN.I" : "MAIN.H");
        request.ncRoot = tree.root;
        request.text = text;
        const task::RunCheck check = task::checkByRunning(*mill, request);
        EXPECT_FALSE(hasErrors(check.diagnostics)) << text << "\n"
                                                   << check.diagnostics.back().format();
    }
}

// A folder is no program (the list stays open and says so); a link that leads out of the root
// is refused with the reason and leaves the field as it was.
TEST(ProgramFile, AFolderOrALinkOutOfTheRootIsNotTaken) {
    test::testApp();
    const NcTree tree = makeTree("program_file_refused");
    SpecialFunctionDialog dialog(SpecialFunction::CallProgram, {tree.root, tree.root});
    auto* field = qobject_cast<QLineEdit*>(dialog.input(0));
    field->setText("SUB");
    bool folderRefused = false;
    answerNextDialog<ProgramFileDialog>([&](ProgramFileDialog& files) {
        ASSERT_TRUE(QTest::qWaitFor([&] { return files.selectPath(tree.root / "OTHER"); }, 5000));
        files.accept();
        folderRefused = files.isVisible() && files.message() == "Choose a program (.H or .I)";
        chooseInList(files, tree.root, tree.root / "OUT.H");
    });
    EXPECT_FALSE(dialog.selectFile());
    EXPECT_TRUE(folderRefused);
    EXPECT_EQ(dialog.message().toStdString(),
              "'" + (tree.root / "OUT.H").string() + "' is outside the NC root");
    EXPECT_EQ(field->text(), "SUB");
    // Without an NC root there is no list to choose from.
    EXPECT_EQ(SpecialFunctionDialog(SpecialFunction::CallProgram).selectFileButton(), nullptr);
    EXPECT_EQ(SpecialFunctionDialog(SpecialFunction::PlaneSpatial, {tree.root, tree.root})
                  .selectFileButton(),
              nullptr);
}

}  // namespace
}  // namespace kerf::ui
