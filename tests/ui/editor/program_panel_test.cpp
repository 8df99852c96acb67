#include "ui/editor/program_panel.h"

#include <QAbstractTextDocumentLayout>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>
#include <QTextBlock>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/common/diagnostic_text.h"
#include "ui/editor/program_checker.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_file.h"

namespace kerf::ui {
namespace {

ProgramPanel::Settings settingsIn(const std::filesystem::path& dir) {
    ProgramPanel::Settings settings;
    settings.machine = *machine::loadMachine("mill");
    settings.ncRoot = dir;
    settings.recoveryFolder = dir / "recovery";
    settings.autosaveDelayMs = 60000;  // the tests autosave explicitly
    return settings;
}

void writeFile(const std::filesystem::path& path, std::string_view bytes) {
    ASSERT_FALSE(writeFileAtomically(path, bytes).has_value());
}

std::string readFile(const std::filesystem::path& path) {
    return readWholeFile(path).value();
}

TEST(ProgramPanel, SaveKeepsLineEndsAndEncoding) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_save");
    // CRLF line ends and a cp1252 "é" (0xE9) in a comment, as a PC-written TNC file has them.
    writeFile(dir / "A.H", "0 BEGIN PGM A MM\r\n1 L Z+50 R0 FMAX ; caf\xE9\r\n2 END PGM A MM\r\n");
    ProgramPanel panel(settingsIn(dir));
    ASSERT_TRUE(panel.open(dir / "A.H"));
    EXPECT_EQ(panel.editor()->document()->findBlockByNumber(1).text(),
              QStringLiteral("1 L Z+50 R0 FMAX ; caf\u00e9"));
    QTextCursor cursor(panel.editor()->document()->findBlockByNumber(1));
    cursor.movePosition(QTextCursor::EndOfBlock);
    cursor.insertText("!");
    EXPECT_TRUE(panel.modified());
    ASSERT_TRUE(panel.save());
    EXPECT_FALSE(panel.modified());
    EXPECT_EQ(readFile(dir / "A.H"),
              "0 BEGIN PGM A MM\r\n1 L Z+50 R0 FMAX ; caf\xE9!\r\n2 END PGM A MM\r\n");
}

// A program saved as "Unicode" by a Windows editor: UTF-16 little endian with a byte order mark
// and CRLF. It was shown as bytes (a NUL between the letters, an error on every line).
TEST(ProgramPanel, AUtf16ProgramIsShownAsTextAndSavedAsItWas) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_utf16");
    auto utf16 = [](std::string_view ascii) {
        std::string bytes = "\xFF\xFE";
        for (char c : ascii) {
            bytes += c;
            bytes += '\0';
        }
        return bytes;
    };
    writeFile(dir / "U.H", utf16("0 BEGIN PGM U MM\r\n1 L Z+50 R0 FMAX\r\n2 END PGM U MM\r\n"));
    ProgramPanel panel(settingsIn(dir));
    ASSERT_TRUE(panel.open(dir / "U.H"));
    EXPECT_EQ(panel.editor()->document()->findBlockByNumber(1).text(),
              QStringLiteral("1 L Z+50 R0 FMAX"));
    QTextCursor cursor(panel.editor()->document()->findBlockByNumber(1));
    cursor.movePosition(QTextCursor::EndOfBlock);
    cursor.insertText(" M3");
    ASSERT_TRUE(panel.save());
    EXPECT_EQ(readFile(dir / "U.H"),
              utf16("0 BEGIN PGM U MM\r\n1 L Z+50 R0 FMAX M3\r\n2 END PGM U MM\r\n"));
}

TEST(ProgramPanel, AutosaveSurvivesACrashAndIsOfferedOnReopen) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_recovery");
    const std::string original = "0 BEGIN PGM B MM\n1 END PGM B MM\n";
    writeFile(dir / "B.H", original);
    {
        ProgramPanel panel(settingsIn(dir));
        ASSERT_TRUE(panel.open(dir / "B.H"));
        EXPECT_FALSE(panel.recoveryAvailable());
        panel.editor()->goToLine(1);
        panel.editor()->moveCursor(QTextCursor::EndOfBlock);
        panel.editor()->insertBlock();
        panel.editor()->insertPlainText("L Z+100 R0 FMAX");
        panel.autosave();
        // The panel goes away without saving, as in a crash.
    }
    EXPECT_EQ(readFile(dir / "B.H"), original);
    ProgramPanel panel(settingsIn(dir));
    ASSERT_TRUE(panel.open(dir / "B.H"));
    ASSERT_TRUE(panel.recoveryAvailable());
    panel.restoreRecovery();
    EXPECT_EQ(panel.editor()->toPlainText(),
              QStringLiteral("0 BEGIN PGM B MM\n1 L Z+100 R0 FMAX\n2 END PGM B MM\n"));
    ASSERT_TRUE(panel.save());
    EXPECT_EQ(readFile(dir / "B.H"), "0 BEGIN PGM B MM\n1 L Z+100 R0 FMAX\n2 END PGM B MM\n");
    // Saved: the copy is gone, so the next opening offers nothing.
    ProgramPanel again(settingsIn(dir));
    ASSERT_TRUE(again.open(dir / "B.H"));
    EXPECT_FALSE(again.recoveryAvailable());
}

TEST(ProgramPanel, RecoveryCopyOfAnotherProgramIsNotOffered) {
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_owner");
    RecoveryStore store(dir / "recovery");
    ASSERT_FALSE(store.store(dir / "C.H", "text").has_value());
    EXPECT_EQ(store.recover(dir / "C.H"), QStringLiteral("text"));
    EXPECT_FALSE(store.recover(dir / "D.H").has_value());
    store.discard(dir / "C.H");
    EXPECT_FALSE(store.recover(dir / "C.H").has_value());
}

TEST(ProgramPanel, CheckReportsTheLineOfAnError) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_check");
    // Line 3 (block 2) holds a word that is no Klartext function.
    writeFile(dir / "E.H", "0 BEGIN PGM E MM\n1 L Z+50 R0 FMAX\n2 BOGUS WORD\n3 END PGM E MM\n");
    ProgramPanel panel(settingsIn(dir));
    QSignalSpy spy(&panel, &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(panel.open(dir / "E.H"));
    ASSERT_TRUE(spy.wait(10000));
    bool errorOnLine3 = false;
    for (const Diagnostic& d : panel.diagnostics())
        errorOnLine3 |= d.severity == Severity::Error && d.line == 3;
    EXPECT_TRUE(errorOnLine3);
    // Fixing the line and checking again clears the error.
    QTextCursor cursor(panel.editor()->document()->findBlockByNumber(2));
    cursor.select(QTextCursor::BlockUnderCursor);
    cursor.movePosition(QTextCursor::StartOfBlock);
    cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
    cursor.insertText("2 L X+0 R0 FMAX");
    panel.checkNow();
    ASSERT_TRUE(spy.wait(10000));
    EXPECT_FALSE(hasErrors(panel.diagnostics()));
}

// "Check program" tells what `kerf check` tells: the program runs dry (task::checkByRunning),
// so a division by zero that only the run meets is an error at its operator, in the list the
// editor jumps from, with a message that sums the check up.
TEST(ProgramPanel, CheckProgramRunsTheProgramAsKerfCheckDoes) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_run_check");
    writeFile(dir / "D.H",
              "0 BEGIN PGM D MM\n1 Q1 = 0\n2 Q2 = 5 / Q1\n3 L Z+50 R0 FMAX\n4 END PGM D MM\n");
    ProgramPanel panel(settingsIn(dir));
    QSignalSpy changed(&panel, &ProgramPanel::diagnosticsChanged);
    QSignalSpy messages(&panel, &ProgramPanel::message);
    ASSERT_TRUE(panel.open(dir / "D.H"));
    ASSERT_TRUE(changed.wait(10000));
    EXPECT_FALSE(hasErrors(panel.diagnostics()));  // the static check cannot see it
    messages.clear();
    panel.checkProgram();
    EXPECT_TRUE(panel.checkingProgram());
    auto* title = panel.findChild<QLabel*>("programTitle");
    ASSERT_NE(title, nullptr);
    EXPECT_TRUE(title->text().contains("Checking the program")) << title->text().toStdString();
    ASSERT_TRUE(changed.wait(10000));
    EXPECT_FALSE(panel.checkingProgram());
    EXPECT_EQ(title->text(), "D.H");
    ASSERT_TRUE(hasErrors(panel.diagnostics()));
    const Diagnostic& error = panel.diagnostics().back();
    EXPECT_EQ(error.line, 3u);  // "2 Q2 = 5 / Q1", the '/' at column 10
    EXPECT_EQ(error.column, 10u);
    EXPECT_EQ(error.messageTemplate, "division by zero");
    // The summary is a note: the message line shows the error itself, the most serious.
    ASSERT_EQ(messages.size(), 1);
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Note);
    EXPECT_EQ(messages.at(0).at(1).toString(), "Program check: the program cannot run (errors: 1)");

    // With the divisor fixed the check passes and says so.
    QTextCursor cursor(panel.editor()->document()->findBlockByNumber(1));
    cursor.movePosition(QTextCursor::EndOfBlock);
    cursor.insertText("+2");
    messages.clear();
    panel.checkProgram();
    ASSERT_TRUE(changed.wait(10000));
    EXPECT_FALSE(hasErrors(panel.diagnostics()));
    ASSERT_EQ(messages.size(), 1);
    EXPECT_EQ(messages.at(0).at(1).toString(),
              "Program check: no errors, the program runs to its end");
}

// An endless loop ends the check at the block limit; the message says so without naming
// `kerf check`'s --max-blocks, which the panel does not have (it did before).
TEST(ProgramPanel, TheCheckOfAnEndlessLoopNamesNoCommandLineOption) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_run_check_limit");
    writeFile(dir / "L.H",
              "0 BEGIN PGM L MM\n1 LBL 1\n2 FN 9: IF +0 EQU +0 GOTO LBL 1\n3 END PGM L MM\n");
    ProgramPanel panel(settingsIn(dir));
    QSignalSpy changed(&panel, &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(panel.open(dir / "L.H"));
    ASSERT_TRUE(changed.wait(10000));
    panel.checkProgram();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !panel.checkingProgram(); }, 120000));
    ASSERT_FALSE(panel.diagnostics().empty());
    const Diagnostic& limit = panel.diagnostics().back();
    EXPECT_EQ(limit.code, "block-limit");
    EXPECT_EQ(translatedMessage(limit).toStdString(),
              "the program check stopped after 10000000 blocks: endless loop?");
}

// An edit during the run of the check cancels it: the endless loop would keep the worker busy
// for its ten million blocks, yet the static check of the edited text comes back, and no
// summary speaks for the text that is gone.
TEST(ProgramPanel, AnEditCancelsTheCheckProgramRun) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_run_check_cancel");
    writeFile(dir / "L.H",
              "0 BEGIN PGM L MM\n1 LBL 1\n2 FN 9: IF +0 EQU +0 GOTO LBL 1\n3 END PGM L MM\n");
    auto settings = settingsIn(dir);
    settings.checkDelayMs = 0;
    ProgramPanel panel(settings);
    QSignalSpy changed(&panel, &ProgramPanel::diagnosticsChanged);
    QSignalSpy messages(&panel, &ProgramPanel::message);
    ASSERT_TRUE(panel.open(dir / "L.H"));
    ASSERT_TRUE(changed.wait(10000));
    panel.checkProgram();
    QTest::qWait(50);  // the worker is in the loop
    changed.clear();
    QTextCursor cursor(panel.editor()->document()->findBlockByNumber(2));
    cursor.movePosition(QTextCursor::EndOfBlock);
    cursor.insertText(" ; edited");
    EXPECT_FALSE(panel.checkingProgram());
    ASSERT_TRUE(changed.wait(10000));
    EXPECT_FALSE(hasErrors(panel.diagnostics()));
    for (const QList<QVariant>& message : messages)
        EXPECT_FALSE(message.at(1).toString().contains(QStringLiteral("Program check")));
}

TEST(ProgramPanel, LargeFilesLoadInTheBackground) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_background");
    writeFile(dir / "F.H", "0 BEGIN PGM F MM\n1 L Z+50 R0 FMAX\n2 END PGM F MM\n");
    auto settings = settingsIn(dir);
    settings.backgroundLoadBytes = 0;  // every file counts as large
    ProgramPanel panel(settings);
    QSignalSpy opened(&panel, &ProgramPanel::fileChanged);
    ASSERT_TRUE(panel.open(dir / "F.H"));
    EXPECT_TRUE(panel.loading());
    EXPECT_TRUE(panel.editor()->isReadOnly());
    ASSERT_TRUE(opened.wait(10000));
    EXPECT_FALSE(panel.loading());
    EXPECT_FALSE(panel.editor()->isReadOnly());
    EXPECT_EQ(panel.path(), dir / "F.H");
    EXPECT_EQ(panel.editor()->toPlainText(),
              QStringLiteral("0 BEGIN PGM F MM\n1 L Z+50 R0 FMAX\n2 END PGM F MM\n"));
    EXPECT_FALSE(panel.modified());
    // The adopted document is edited, undone and saved like any other.
    panel.editor()->goToLine(2);
    panel.editor()->moveCursor(QTextCursor::EndOfBlock);
    panel.editor()->insertBlock();
    EXPECT_TRUE(panel.modified());
    EXPECT_EQ(panel.editor()->document()->findBlockByNumber(3).text(),
              QStringLiteral("3 END PGM F MM"));
    QSignalSpy messages(&panel, &ProgramPanel::message);
    ASSERT_TRUE(panel.save());
    // A large file is written by a worker, with the editor read-only until it is on disk.
    EXPECT_TRUE(panel.editor()->isReadOnly());
    ASSERT_TRUE(messages.wait(10000));
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Note);
    EXPECT_FALSE(panel.editor()->isReadOnly());
    EXPECT_FALSE(panel.modified());
    EXPECT_EQ(readFile(dir / "F.H"), "0 BEGIN PGM F MM\n1 L Z+50 R0 FMAX\n2 \n3 END PGM F MM\n");
    panel.editor()->undo();
    EXPECT_EQ(panel.editor()->document()->findBlockByNumber(2).text(),
              QStringLiteral("2 END PGM F MM"));
}

// A 10 MB line kept the panel busy for minutes (Qt lays out and shapes a line as a whole; `kerf
// --program` with a 10 MB formula line had not drawn after 180 s). No dialect runs a block that
// long, so the editor does not open it: an error names the line, the program shown stays.
TEST(ProgramPanel, AFileWithALineLongerThanABlockIsNotOpened) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_long_line");
    writeFile(dir / "A.H", "0 BEGIN PGM A MM\n1 L Z+50 R0 FMAX\n2 END PGM A MM\n");
    const std::string fits = "1 ; " + std::string(60000 - 4, 'x');
    writeFile(dir / "FITS.H", "0 BEGIN PGM FITS MM\r\n" + fits + "\r\n2 END PGM FITS MM\r\n");
    writeFile(dir / "LONG.H", "0 BEGIN PGM LONG MM\n" + fits + "x\n2 END PGM LONG MM\n");
    // CR-only line ends: the third line is too long.
    writeFile(dir / "CR.H", "0 BEGIN PGM CR MM\r1 L Z+50 R0 FMAX\r" + fits + "x\r");
    ProgramPanel panel(settingsIn(dir));
    ASSERT_TRUE(panel.open(dir / "A.H"));
    ASSERT_TRUE(panel.open(dir / "FITS.H"));
    EXPECT_EQ(panel.editor()->document()->findBlockByNumber(1).text().size(), 60000);
    ASSERT_TRUE(panel.open(dir / "A.H"));
    QSignalSpy messages(&panel, &ProgramPanel::message);
    EXPECT_FALSE(panel.open(dir / "LONG.H"));
    ASSERT_EQ(messages.size(), 1);
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Error);
    EXPECT_TRUE(messages.at(0).at(1).toString().startsWith(
        QStringLiteral("the block is longer than 60000 characters")))
        << messages.at(0).at(1).toString().toStdString();
    EXPECT_EQ(panel.path(), dir / "A.H");
    EXPECT_EQ(panel.editor()->document()->blockCount(), 4);  // A.H and the empty last line
    const auto error = readProgramFile(dir / "CR.H");
    ASSERT_FALSE(error);
    EXPECT_EQ(error.error().line, 3u);
    EXPECT_EQ(error.error().column, 60001u);
    EXPECT_TRUE(readProgramFile(dir / "FITS.H"));
    // The same through the background loader of large files.
    auto settings = settingsIn(dir);
    settings.backgroundLoadBytes = 0;
    ProgramPanel background(settings);
    QSignalSpy failed(&background, &ProgramPanel::message);
    ASSERT_TRUE(background.open(dir / "LONG.H"));
    ASSERT_TRUE(failed.wait(10000));
    EXPECT_EQ(failed.at(0).at(0).value<Severity>(), Severity::Error);
    EXPECT_TRUE(failed.at(0).at(1).toString().startsWith(
        QStringLiteral("the block is longer than 60000 characters")));
    EXPECT_FALSE(background.loading());
}

// A program loaded in the background showed in the application's font (smaller than the
// editor's 13 pt): QPlainTextEdit::setDocument keeps a document's own default font.
TEST(ProgramPanel, ABackgroundLoadShowsTheProgramInTheEditorsFont) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_background_font");
    writeFile(dir / "F.H", "0 BEGIN PGM F MM\n1 L Z+50 R0 FMAX\n2 END PGM F MM\n");
    ProgramPanel typed(settingsIn(dir));
    ASSERT_TRUE(typed.open(dir / "F.H"));
    ASSERT_FALSE(typed.loading());
    auto settings = settingsIn(dir);
    settings.backgroundLoadBytes = 0;  // every file counts as large
    ProgramPanel background(settings);
    QSignalSpy opened(&background, &ProgramPanel::fileChanged);
    ASSERT_TRUE(background.open(dir / "F.H"));
    ASSERT_TRUE(opened.wait(10000));
    // Both show the text in the editor's font, the 13 pt set for programs.
    for (ProgramPanel* panel : {&typed, &background}) {
        const QFont shown = panel->editor()->document()->defaultFont();
        EXPECT_EQ(shown.pointSize(), 13);
        EXPECT_EQ(shown, panel->editor()->font());
    }
    // And the lines are laid out alike: the same height.
    const auto lineHeight = [](ProgramPanel& panel) {
        QTextDocument* document = panel.editor()->document();
        return document->documentLayout()->blockBoundingRect(document->firstBlock()).height();
    };
    EXPECT_DOUBLE_EQ(lineHeight(background), lineHeight(typed));
}

// "Save" before opening another program: a long program is written by a worker, and the other
// program opens once the edits are on disk (the open was dropped without a word before, the
// operator left on the file manager); when the save fails, it does not open and says why.
TEST(ProgramPanel, AProgramAskedForDuringASaveOpensWhenTheEditsAreOnDisk) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_open_after_save");
    writeFile(dir / "A.H", "0 BEGIN PGM A MM\n1 END PGM A MM\n");
    writeFile(dir / "B.H", "0 BEGIN PGM B MM\n1 END PGM B MM\n");
    writeFile(dir / "C.H", "0 BEGIN PGM C MM\n1 END PGM C MM\n");
    auto settings = settingsIn(dir);
    settings.backgroundLoadBytes = 0;  // every file counts as large: written by the worker
    ProgramPanel panel(settings);
    QSignalSpy opened(&panel, &ProgramPanel::fileChanged);
    ASSERT_TRUE(panel.open(dir / "A.H"));
    ASSERT_TRUE(opened.wait(10000));
    panel.editor()->goToLine(1);
    panel.editor()->moveCursor(QTextCursor::EndOfBlock);
    panel.editor()->insertPlainText(" ; edited");
    ASSERT_TRUE(panel.save());
    ASSERT_TRUE(panel.open(dir / "B.H"));  // under way: after the save
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return panel.path() == dir / "B.H" && !panel.loading(); }, 10000));
    EXPECT_EQ(readFile(dir / "A.H"), "0 BEGIN PGM A MM ; edited\n1 END PGM A MM\n");
    EXPECT_EQ(panel.editor()->toPlainText(), QStringLiteral("0 BEGIN PGM B MM\n1 END PGM B MM\n"));

    // B.H is replaced by a link on disk: Kerf does not write through links, the save fails and
    // C.H stays unopened, B's edits on the screen.
    panel.editor()->goToLine(1);
    panel.editor()->moveCursor(QTextCursor::EndOfBlock);
    panel.editor()->insertPlainText(" ; kept");
    std::filesystem::remove(dir / "B.H");
    std::filesystem::create_symlink(dir / "A.H", dir / "B.H");
    QSignalSpy messages(&panel, &ProgramPanel::message);
    ASSERT_TRUE(panel.save());
    ASSERT_TRUE(panel.open(dir / "C.H"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return messages.size() >= 2; }, 10000));
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Error);
    EXPECT_EQ(messages.at(1).at(1).toString(), "C.H was not opened: B.H could not be saved");
    QTest::qWait(50);
    EXPECT_EQ(panel.path(), dir / "B.H");
    EXPECT_TRUE(panel.modified());
    EXPECT_TRUE(panel.editor()->toPlainText().contains(" ; kept"));
}

// A program of `blocks` straight moves, without errors.
std::string manyBlocks(int blocks) {
    std::string text = "0 BEGIN PGM BIG MM\n";
    for (int i = 1; i <= blocks; ++i)
        text += std::to_string(i) + " L X+" + std::to_string(i % 100) + " R0 FMAX\n";
    return text + std::to_string(blocks + 1) + " END PGM BIG MM\n";
}

// Issue 14: with a program's errors underlined, opening a large program (read in the
// background) crashed the HMI when the new program's check came back (setDiagnostics ->
// setExtraSelections over selections into the replaced document). Here a check of the first
// program is also under way when the second one is opened: its result must not land on the new
// document either.
TEST(ProgramPanel, ChecksOfAReplacedDocumentDoNotLandOnTheNewOne) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_swap");
    writeFile(dir / "E.H", "0 BEGIN PGM E MM\n1 L Z+50 R0 FMAX\n2 BOGUS WORD\n3 END PGM E MM\n");
    writeFile(dir / "BIG.H", manyBlocks(20000));
    auto settings = settingsIn(dir);
    settings.backgroundLoadBytes = 4096;  // BIG.H (~300 kB) loads in the background
    ProgramPanel panel(settings);
    QSignalSpy diagnostics(&panel, &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(panel.open(dir / "E.H"));
    ASSERT_TRUE(diagnostics.wait(10000));
    ASSERT_TRUE(hasErrors(panel.diagnostics()));
    ASSERT_EQ(panel.editor()->extraSelections().size(), 1);  // line 3 underlined

    // An edit is being checked when the large program is opened.
    QTextCursor cursor(panel.editor()->document()->findBlockByNumber(1));
    cursor.movePosition(QTextCursor::EndOfBlock);
    cursor.insertText(" ");
    panel.checkNow();
    QSignalSpy opened(&panel, &ProgramPanel::fileChanged);
    ASSERT_TRUE(panel.open(dir / "BIG.H"));
    ASSERT_TRUE(panel.loading());
    // Nothing of the old program is shown while the new one is read.
    EXPECT_TRUE(panel.diagnostics().empty());
    EXPECT_TRUE(panel.editor()->extraSelections().isEmpty());
    ASSERT_TRUE(opened.wait(10000));
    // Every check that was asked for reports (or is dropped) within a few seconds; the last
    // result shown is BIG.H's own: no error, nothing underlined.
    diagnostics.clear();
    ASSERT_TRUE(diagnostics.wait(20000));
    QTest::qWait(500);  // a stale result would come after it
    EXPECT_FALSE(hasErrors(panel.diagnostics()));
    for (const QTextEdit::ExtraSelection& s : panel.editor()->extraSelections())
        EXPECT_EQ(s.cursor.document(), panel.editor()->document());
    EXPECT_TRUE(panel.editor()->extraSelections().isEmpty());
    // A late result of an earlier request (here E.H's first check, request 1) is dropped, even
    // when it names the file shown now.
    Diagnostic late =
        Diagnostic::make(Severity::Error, "syntax", (dir / "BIG.H").string(), 5, 1, "late");
    emit panel.checker()->checked(1, {late});
    EXPECT_FALSE(hasErrors(panel.diagnostics()));
    EXPECT_TRUE(panel.editor()->extraSelections().isEmpty());
    // The editor still works on the new document.
    panel.editor()->goToLine(20000);
    EXPECT_EQ(panel.editor()->currentLine(), 20000);
}

TEST(ProgramPanel, LongProgramIsRenumberedThenSaved) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_renumber_save");
    // BEGIN PGM, then a two-line cycle definition, then plain blocks up to the live limit.
    std::string text = "0 BEGIN PGM G MM\n1 CYCL DEF 200 DRILLING ~\n  Q200=2 ;SET-UP CLEARANCE\n";
    const int blocks = ProgramEditor::kLiveRenumberLimit + 5;
    for (int n = 2; n < blocks; ++n)
        text += std::to_string(n) + " L X+" + std::to_string(n) + " FMAX\n";
    writeFile(dir / "G.H", text);
    ProgramPanel panel(settingsIn(dir));
    ASSERT_TRUE(panel.open(dir / "G.H"));
    panel.editor()->goToLine(1);
    panel.editor()->moveCursor(QTextCursor::EndOfBlock);
    panel.editor()->insertBlock();  // "1 " after BEGIN PGM; the rest is renumbered on save
    ASSERT_TRUE(panel.editor()->numbersStale());
    QSignalSpy messages(&panel, &ProgramPanel::message);
    ASSERT_TRUE(panel.save());
    if (messages.isEmpty()) {
        ASSERT_TRUE(messages.wait(20000));
    }
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Note);
    EXPECT_FALSE(panel.modified());
    // Every block after the new one moved up by one; the parameter line stays unnumbered.
    std::string expected =
        "0 BEGIN PGM G MM\n1 \n2 CYCL DEF 200 DRILLING ~\n  Q200=2 ;SET-UP CLEARANCE\n";
    for (int n = 2; n < blocks; ++n)
        expected += std::to_string(n + 1) + " L X+" + std::to_string(n) + " FMAX\n";
    EXPECT_EQ(readFile(dir / "G.H"), expected);
}

TEST(ProgramPanel, MissingFileIsAMessageNotACrash) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_missing");
    ProgramPanel panel(settingsIn(dir));
    QSignalSpy spy(&panel, &ProgramPanel::message);
    EXPECT_FALSE(panel.open(dir / "NONE.H"));
    ASSERT_EQ(spy.count(), 1);
    EXPECT_EQ(spy.at(0).at(0).value<Severity>(), Severity::Error);
}

// Opening a file that cannot be read leaves the program shown as it was, its errors still
// underlined and listed.
TEST(ProgramPanel, AFailedOpenKeepsTheShownProgramsDiagnostics) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_panel_failed_open");
    writeFile(dir / "E.H", "0 BEGIN PGM E MM\n1 L Z+50 R0 FMAX\n2 BOGUS WORD\n3 END PGM E MM\n");
    ProgramPanel panel(settingsIn(dir));
    QSignalSpy diagnostics(&panel, &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(panel.open(dir / "E.H"));
    ASSERT_TRUE(diagnostics.wait(10000));
    ASSERT_TRUE(hasErrors(panel.diagnostics()));
    diagnostics.clear();
    EXPECT_FALSE(panel.open(dir / "NONE.H"));
    EXPECT_EQ(diagnostics.count(), 0);
    EXPECT_TRUE(hasErrors(panel.diagnostics()));
    EXPECT_EQ(panel.editor()->extraSelections().size(), 1);
    EXPECT_EQ(panel.path(), dir / "E.H");
}

}  // namespace
}  // namespace kerf::ui
