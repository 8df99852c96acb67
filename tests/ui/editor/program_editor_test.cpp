#include "ui/editor/program_editor.h"

#include <QLineEdit>
#include <QPlainTextDocumentLayout>
#include <QPointer>
#include <QSignalSpy>
#include <QTest>
#include <QTextBlock>
#include <QTextLayout>
#include <optional>

#include <gtest/gtest.h>

#include "qt_test_app.h"
#include "ui/editor/find_bar.h"
#include "ui/editor/renumber_job.h"
#include "ui/editor/visible_highlighter.h"

namespace kerf::ui {
namespace {

using program::Dialect;

QString lines(std::initializer_list<const char*> text) {
    QStringList list;
    for (const char* line : text)
        list << QString::fromUtf8(line);
    return list.join('\n');
}

void placeCursorAtEndOfLine(ProgramEditor& editor, int line) {
    QTextCursor cursor(editor.document()->findBlockByNumber(line - 1));
    cursor.movePosition(QTextCursor::EndOfBlock);
    editor.setTextCursor(cursor);
}

TEST(ProgramEditor, EnterInsertsANumberedBlockAndRenumbersTheRest) {
    test::testApp();
    ProgramEditor editor;
    editor.setPlainText(
        lines({"0 BEGIN PGM A MM", "1 L Z+50 R0 FMAX", "2 L X+0 Y+0 R0 FMAX", "3 END PGM A MM"}));
    placeCursorAtEndOfLine(editor, 2);
    QTest::keyClick(&editor, Qt::Key_Return);
    QTest::keyClicks(&editor, "L Z+2");
    EXPECT_EQ(editor.toPlainText(), lines({"0 BEGIN PGM A MM", "1 L Z+50 R0 FMAX", "2 L Z+2",
                                           "3 L X+0 Y+0 R0 FMAX", "4 END PGM A MM"}));
    // The new block and the renumbering are one undo step; the typed text is another.
    editor.undo();
    editor.undo();
    EXPECT_EQ(editor.toPlainText(), lines({"0 BEGIN PGM A MM", "1 L Z+50 R0 FMAX",
                                           "2 L X+0 Y+0 R0 FMAX", "3 END PGM A MM"}));
}

TEST(ProgramEditor, ShiftEnterBreaksTheLineWithoutANumber) {
    test::testApp();
    ProgramEditor editor;
    editor.setPlainText(lines({"0 BEGIN PGM A MM", "1 END PGM A MM"}));
    placeCursorAtEndOfLine(editor, 1);
    QTest::keyClick(&editor, Qt::Key_Return, Qt::ShiftModifier);
    EXPECT_EQ(editor.toPlainText(), lines({"0 BEGIN PGM A MM", "", "1 END PGM A MM"}));
    EXPECT_EQ(editor.document()->blockCount(), 3);
}

TEST(ProgramEditor, IsoBlocksKeepTheirStep) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(Dialect::Fagor);
    editor.setPlainText(lines({"N10 G90", "N20 G00 X0", "N30 M30"}));
    placeCursorAtEndOfLine(editor, 2);
    editor.insertBlock();
    EXPECT_EQ(editor.toPlainText(), lines({"N10 G90", "N20 G00 X0", "N30 ", "N40 M30"}));
}

TEST(ProgramEditor, FagorReferencesFollowTheirLabelsWhenABlockIsInserted) {
    // The inserted block takes N30; the old N30 becomes N40, and the jump to it follows.
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(Dialect::Fagor);
    editor.setPlainText(lines({"N10 G90", "N20 (GOTO N30)", "N30 M30"}));
    placeCursorAtEndOfLine(editor, 2);
    editor.insertBlock();
    EXPECT_EQ(editor.toPlainText(), lines({"N10 G90", "N20 (GOTO N40)", "N30 ", "N40 M30"}));
    editor.undo();
    EXPECT_EQ(editor.toPlainText(), lines({"N10 G90", "N20 (GOTO N30)", "N30 M30"}));
}

void placeCursor(ProgramEditor& editor, int line, int column) {
    QTextCursor cursor(editor.document()->findBlockByNumber(line - 1));
    cursor.setPosition(cursor.position() + column);
    editor.setTextCursor(cursor);
}

// Enter in a FAGOR program; the problem it reported, if any.
std::optional<RenumberProblem> pressEnter(ProgramEditor& editor) {
    std::optional<RenumberProblem> reported;
    const auto connection =
        QObject::connect(&editor, &ProgramEditor::labelsKept,
                         [&reported](const RenumberProblem& problem) { reported = problem; });
    QTest::keyClick(&editor, Qt::Key_Return);
    QObject::disconnect(connection);
    return reported;
}

TEST(ProgramEditor, EnterOnAFagorLabelOpensABlockBeforeItsLine) {
    // With the cursor on N30 (before it, inside it, or between it and its words) the new block
    // goes before the line, which keeps its words and moves down as N40 with the jump to it. A
    // split there would have left "N3" and a line "N40 0 M30".
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(Dialect::Fagor);
    const QString program = lines({"N10 G90", "N20 (GOTO N30)", "N30 M30"});
    for (const int column : {0, 2, 3, 4}) {
        SCOPED_TRACE(column);
        editor.setPlainText(program);
        placeCursor(editor, 3, column);
        EXPECT_FALSE(pressEnter(editor));
        EXPECT_EQ(editor.toPlainText(), lines({"N10 G90", "N20 (GOTO N40)", "N30 ", "N40 M30"}));
        QTest::keyClicks(&editor, "G00 X10");
        EXPECT_EQ(editor.document()->findBlockByNumber(2).text(), QStringLiteral("N30 G00 X10"));
    }
    // A line that holds only its label: Enter at its end opens the next block as before.
    editor.setPlainText(lines({"N10 G90", "N20", "N30 M30"}));
    placeCursorAtEndOfLine(editor, 2);
    EXPECT_FALSE(pressEnter(editor));
    EXPECT_EQ(editor.toPlainText(), lines({"N10 G90", "N20", "N30 ", "N40 M30"}));
}

TEST(ProgramEditor, EnterOnAKlartextBlockNumberOpensABlockBeforeIt) {
    test::testApp();
    ProgramEditor editor;
    editor.setPlainText(lines({"0 BEGIN PGM A MM", "1 L Z+50 R0 FMAX", "2 END PGM A MM"}));
    placeCursor(editor, 2, 0);
    QTest::keyClick(&editor, Qt::Key_Return);
    QTest::keyClicks(&editor, "TOOL CALL 1 Z S2000");
    EXPECT_EQ(editor.toPlainText(), lines({"0 BEGIN PGM A MM", "1 TOOL CALL 1 Z S2000",
                                           "2 L Z+50 R0 FMAX", "3 END PGM A MM"}));
}

TEST(ProgramEditor, EnterThatWouldBreakAFagorReferenceLeavesTheLabelsAsTheyAre) {
    using Kind = RenumberProblem::Kind;
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(Dialect::Fagor);
    // A jump through a parameter: N30 must stay N30, so the new line after N10 gets no label.
    editor.setPlainText(lines({"N10 (P1 = 30)", "N20 (GOTO N P1)", "N30 M30"}));
    placeCursorAtEndOfLine(editor, 1);
    auto problem = pressEnter(editor);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, Kind::ComputedReference);
    EXPECT_EQ(problem->line, 3);  // the GOTO, one line down now
    EXPECT_EQ(editor.toPlainText(), lines({"N10 (P1 = 30)", "", "N20 (GOTO N P1)", "N30 M30"}));
    // After the last label nothing moves: the new line is numbered.
    placeCursorAtEndOfLine(editor, 4);
    EXPECT_FALSE(pressEnter(editor));
    EXPECT_EQ(editor.document()->lastBlock().text(), QStringLiteral("N40 "));

    // The profile's last label would go from N9990 to N10000; G68 takes 4 digits.
    const QString profile = lines({"N9960 G90", "N9970 G68 X0 Z0 C2 D1 S9980 E9990",
                                   "N9980 G01 X20 Z0", "N9990 G01 X40 Z-10"});
    editor.setPlainText(profile);
    placeCursorAtEndOfLine(editor, 1);
    problem = pressEnter(editor);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, Kind::ProfileLabelTooLong);
    EXPECT_EQ(problem->line, 3);
    EXPECT_EQ(problem->label, 10000);
    EXPECT_EQ(editor.toPlainText(), lines({"N9960 G90", "", "N9970 G68 X0 Z0 C2 D1 S9980 E9990",
                                           "N9980 G01 X20 Z0", "N9990 G01 X40 Z-10"}));

    // After N20 comes N100: the new N30 would be the second N30, and the jump would land on
    // whichever came first.
    editor.setPlainText(
        lines({"N10 G90", "N20 (GOTO N30)", "N100 M30", "N30 G00 X10", "N40 (GOTO N100)"}));
    placeCursorAtEndOfLine(editor, 2);
    problem = pressEnter(editor);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, Kind::LabelInUse);
    EXPECT_EQ(problem->line, 3);
    EXPECT_EQ(problem->label, 30);
    EXPECT_EQ(problem->otherLine, 5);
    EXPECT_EQ(editor.toPlainText(), lines({"N10 G90", "N20 (GOTO N30)", "", "N100 M30",
                                           "N30 G00 X10", "N40 (GOTO N100)"}));
    // The same when a renumbered label would meet one that stays.
    editor.setPlainText(lines({"N10 G90", "N20 G00 X0", "N30 M30", "N40 (RET)"}));
    placeCursorAtEndOfLine(editor, 2);
    EXPECT_FALSE(pressEnter(editor));  // N30 -> N40, N40 -> N50: they all move
    EXPECT_EQ(editor.toPlainText(),
              lines({"N10 G90", "N20 G00 X0", "N30 ", "N40 M30", "N50 (RET)"}));
    editor.setPlainText(lines({"N10 G90", "N20 G00 X0", "N30 M30", "N100 (SUB 1)", "N40 (RET)"}));
    placeCursorAtEndOfLine(editor, 2);
    problem = pressEnter(editor);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, Kind::LabelInUse);
    EXPECT_EQ(problem->line, 4);  // the old N30, which would become N40
    EXPECT_EQ(problem->label, 40);
    EXPECT_EQ(problem->otherLine, 6);

    // Labels end at N99999999.
    editor.setPlainText(lines({"N99999990 G00 X0"}));
    placeCursorAtEndOfLine(editor, 1);
    problem = pressEnter(editor);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, Kind::LabelTooLong);
    EXPECT_EQ(problem->line, 2);
    EXPECT_EQ(problem->label, 100'000'000);
    EXPECT_EQ(editor.toPlainText(), lines({"N99999990 G00 X0", ""}));
}

TEST(ProgramEditor, RenumberingAFagorProgramKeepsItsJumpsAndProfilesOnTheirLabels) {
    // From N1 in steps of 10 the profile's N30 and N40 become N71 and N81: the G69's S and E, the
    // GOTO and the labels of RPT follow (the count after it, N3, does not); a comment, and a G68
    // whose profile is in program Q5, do not change.
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(Dialect::Fagor);
    editor.setPlainText(lines({"N1 G90 G95 F0.2 S800 M3", "N2 G00 X70 Z5",
                               "N3 G69 X60 Z-10 C2.5 D1 H0.1 S30 E40 ; S30 E40", "N4 (GOTO N30)",
                               "N5 (RPT N30, N40) N3", "N6 G68 X0 Z0 C2 S30 E40 Q5", "N7 M30",
                               "N30 G01 X40 Z-10", "G01 Z-4", "N40 G01 X20 Z0"}));
    QSignalSpy done(&editor, &ProgramEditor::renumbered);
    editor.renumber();
    ASSERT_EQ(done.size(), 1);
    EXPECT_EQ(editor.toPlainText(),
              lines({"N1 G90 G95 F0.2 S800 M3", "N11 G00 X70 Z5",
                     "N21 G69 X60 Z-10 C2.5 D1 H0.1 S71 E81 ; S30 E40", "N31 (GOTO N71)",
                     "N41 (RPT N71, N81) N3", "N51 G68 X0 Z0 C2 S30 E40 Q5", "N61 M30",
                     "N71 G01 X40 Z-10", "G01 Z-4", "N81 G01 X20 Z0"}));
    editor.undo();  // one step restores numbers and references
    EXPECT_EQ(editor.document()->findBlockByNumber(3).text(), QStringLiteral("N4 (GOTO N30)"));
    EXPECT_EQ(editor.document()->findBlockByNumber(7).text(), QStringLiteral("N30 G01 X40 Z-10"));
}

TEST(ProgramEditor, AFagorProgramIsRenumberedFromTheFirstLabelAndStepChosen) {
    // From N100 in steps of 5: N30 and N40 become N120 and N125; the RPT of program P12 names
    // that program's labels and the SUB and CALL numbers are subroutines, not labels: they stay.
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(Dialect::Fagor);
    editor.setPlainText(lines({"N1 G90 G95 F0.2 S800 M3", "N2 (CALL 7)", "N3 (RPT N30, N40) N2",
                               "N4 (RPT N30, N40, P12)", "N30 G01 X40 Z-10", "N40 G01 X20 Z0",
                               "N5 (GOTO N40)", "N6 (SUB 7)"}));
    QSignalSpy done(&editor, &ProgramEditor::renumbered);
    EXPECT_FALSE(editor.renumber(BlockNumbering{100, 5}));
    ASSERT_EQ(done.size(), 1);
    EXPECT_EQ(editor.toPlainText(),
              lines({"N100 G90 G95 F0.2 S800 M3", "N105 (CALL 7)", "N110 (RPT N120, N125) N2",
                     "N115 (RPT N30, N40, P12)", "N120 G01 X40 Z-10", "N125 G01 X20 Z0",
                     "N130 (GOTO N125)", "N135 (SUB 7)"}));
}

TEST(ProgramEditor, AFagorProgramThatARenumberingWouldBreakStaysAsItIs) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(Dialect::Fagor);
    // A jump through a parameter: no renumbering knows where it lands.
    const QString computed = lines({"N1 (P1 = 30)", "N2 (GOTO N P1)", "N30 M30"});
    editor.setPlainText(computed);
    QSignalSpy done(&editor, &ProgramEditor::renumbered);
    auto problem = editor.renumber();
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, RenumberProblem::Kind::ComputedReference);
    EXPECT_EQ(problem->line, 2);
    EXPECT_EQ(editor.toPlainText(), computed);
    ASSERT_EQ(done.size(), 1);
    EXPECT_FALSE(done.takeFirst().at(0).toBool());
    // From N9990 the profile's first block, the third, would be N9990 + 2 * 10 = N10010: G69
    // takes labels of 4 digits.
    const QString profile =
        lines({"N1 G69 X60 Z-10 C2.5 D1 S3 E4", "N2 M30", "N3 G01 X40 Z-10", "N4 G01 X20 Z0"});
    editor.setPlainText(profile);
    problem = editor.renumber(BlockNumbering{9990, 10});
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, RenumberProblem::Kind::ProfileLabelTooLong);
    EXPECT_EQ(problem->line, 1);
    EXPECT_EQ(problem->label, 10010);
    EXPECT_EQ(editor.toPlainText(), profile);
    EXPECT_FALSE(editor.renumber(BlockNumbering{9960, 10}));  // N9990 is the last: fine
    EXPECT_EQ(editor.document()->firstBlock().text(),
              QStringLiteral("N9960 G69 X60 Z-10 C2.5 D1 S9980 E9990"));
    // Labels end at N99999999: from N99999980 the third block would get N100000000.
    const QString many = lines({"N1 G00 X0", "N2 G00 X1", "N3 M30"});
    editor.setPlainText(many);
    problem = editor.renumber(BlockNumbering{99'999'980, 10});
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->kind, RenumberProblem::Kind::LabelTooLong);
    EXPECT_EQ(problem->line, 3);
    EXPECT_EQ(problem->label, 100'000'000);
    EXPECT_EQ(editor.toPlainText(), many);
}

TEST(ProgramEditor, LongProgramsAreRenumberedInSlicesOnRequest) {
    test::testApp();
    ProgramEditor editor;
    QStringList text;
    for (int i = 0; i < ProgramEditor::kLiveRenumberLimit + 10; ++i)
        text << QStringLiteral("%1 L X+%1").arg(i);
    editor.setPlainText(text.join('\n'));
    placeCursorAtEndOfLine(editor, 1);  // after "0 L X+0"
    editor.insertBlock();
    EXPECT_TRUE(editor.numbersStale());
    EXPECT_EQ(editor.document()->findBlockByNumber(2).text(), QStringLiteral("1 L X+1"));
    QSignalSpy done(&editor, &ProgramEditor::renumbered);
    editor.renumber();
    EXPECT_FALSE(editor.numbersStale());
    if (done.isEmpty()) {
        EXPECT_TRUE(editor.renumbering());
        EXPECT_TRUE(editor.isReadOnly());  // nothing may edit between the slices
        ASSERT_TRUE(done.wait(20000));
    }
    EXPECT_TRUE(done.takeFirst().at(0).toBool());
    EXPECT_FALSE(editor.renumbering());
    EXPECT_FALSE(editor.isReadOnly());
    EXPECT_EQ(editor.document()->findBlockByNumber(1).text(), QStringLiteral("1 "));
    EXPECT_EQ(editor.document()->findBlockByNumber(2).text(), QStringLiteral("2 L X+1"));
    const int last = editor.document()->blockCount() - 1;
    EXPECT_EQ(editor.document()->findBlockByNumber(last).text(),
              QStringLiteral("%1 L X+%2").arg(last).arg(last - 1));
}

TEST(RenumberJob, ManySlicesAreOneUndoStep) {
    test::testApp();
    QTextDocument document;
    QStringList text;
    for (int i = 0; i < 5500; ++i)  // numbered from 1: every block is one too high
        text << QStringLiteral("%1 L X+%2").arg(i + 1).arg(i);
    document.setPlainText(text.join('\n'));
    const QString before = document.toPlainText();
    RenumberJob job(&document, Dialect::Klartext);
    job.setSliceMs(0);  // one check interval (1000 blocks) per slice: six slices
    QSignalSpy done(&job, &RenumberJob::finished);
    job.start();
    ASSERT_TRUE(job.running());
    // After the first slice, block 999 is renumbered and block 1000 not yet.
    EXPECT_EQ(document.findBlockByNumber(999).text(), QStringLiteral("999 L X+999"));
    EXPECT_EQ(document.findBlockByNumber(1000).text(), QStringLiteral("1001 L X+1000"));
    ASSERT_TRUE(done.wait(20000));
    EXPECT_TRUE(done.takeFirst().at(0).toBool());
    EXPECT_EQ(document.findBlockByNumber(5499).text(), QStringLiteral("5499 L X+5499"));
    document.undo();
    EXPECT_EQ(document.toPlainText(), before);
}

TEST(ProgramEditor, AdoptingADocumentFreesThePreviousOne) {
    test::testApp();
    ProgramEditor editor;
    const auto plainDocument = [] {
        auto* document = new QTextDocument;
        document->setDocumentLayout(new QPlainTextDocumentLayout(document));
        return document;
    };
    QPointer<QTextDocument> first = plainDocument();
    editor.adoptDocument(first);
    QPointer<QTextDocument> second = plainDocument();
    editor.adoptDocument(second);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    EXPECT_TRUE(first.isNull());  // a replaced program must not stay in memory
    ASSERT_FALSE(second.isNull());
    EXPECT_EQ(editor.document(), second.data());
}

TEST(ProgramEditor, GoToLineMovesTheCursor) {
    test::testApp();
    ProgramEditor editor;
    editor.setPlainText(lines({"0 A", "1 B", "2 C", "3 D"}));
    editor.goToLine(3);
    EXPECT_EQ(editor.currentLine(), 3);
    EXPECT_EQ(editor.textCursor().block().text(), QStringLiteral("2 C"));
}

TEST(ProgramEditor, OnlyVisibleLinesAreColoured) {
    test::testApp();
    ProgramEditor editor;
    editor.resize(600, 400);
    QStringList text;
    for (int i = 0; i < 50000; ++i)
        text << QStringLiteral("%1 L X+%1 FMAX").arg(i);
    editor.setPlainText(text.join('\n'));
    editor.show();
    QCoreApplication::processEvents();
    editor.highlighter().highlightVisible();
    const QTextBlock first = editor.document()->firstBlock();
    ASSERT_FALSE(first.layout()->formats().isEmpty());
    // "0 L X+0 FMAX": block number, L, X, +0, FMAX.
    EXPECT_EQ(first.layout()->formats().size(), 5);
    EXPECT_EQ(first.layout()->formats()[0].format.foreground(),
              VisibleHighlighter::formatOf(NcToken::BlockNumber).foreground());
    EXPECT_TRUE(editor.document()->findBlockByNumber(40000).layout()->formats().isEmpty());
    // Scrolling there colours it.
    editor.goToLine(40001);
    QCoreApplication::processEvents();
    editor.highlighter().highlightVisible();
    EXPECT_EQ(editor.document()->findBlockByNumber(40000).layout()->formats().size(), 5);
}

TEST(FindBar, ReplaceAllIsOneUndoStep) {
    test::testApp();
    ProgramEditor editor;
    FindBar bar(&editor);
    editor.setPlainText(lines({"0 L X+10 F100", "1 L X+20 F100", "2 L X+30 F200"}));
    bar.findField()->setText("F100");
    bar.replaceField()->setText("F150");
    EXPECT_EQ(bar.replaceAll(), 2);
    EXPECT_EQ(editor.toPlainText(), lines({"0 L X+10 F150", "1 L X+20 F150", "2 L X+30 F200"}));
    editor.undo();
    EXPECT_EQ(editor.toPlainText(), lines({"0 L X+10 F100", "1 L X+20 F100", "2 L X+30 F200"}));
}

TEST(FindBar, ReadOnlyEditorIsNotChanged) {
    test::testApp();
    ProgramEditor editor;
    FindBar bar(&editor);
    editor.setPlainText(lines({"0 L X+10 F100", "1 L X+20 F100"}));
    editor.setReadOnly(true);  // as while a program is renumbered in slices
    bar.findField()->setText("F100");
    bar.replaceField()->setText("F150");
    EXPECT_EQ(bar.replaceAll(), 0);
    EXPECT_TRUE(bar.replaceCurrent());  // still finds
    EXPECT_EQ(editor.toPlainText(), lines({"0 L X+10 F100", "1 L X+20 F100"}));
}

TEST(FindBar, FindWrapsAround) {
    test::testApp();
    ProgramEditor editor;
    FindBar bar(&editor);
    editor.setPlainText(lines({"0 TOOL CALL 1 Z", "1 L X+0", "2 TOOL CALL 2 Z"}));
    bar.findField()->setText("tool call");
    ASSERT_TRUE(bar.findNext());
    EXPECT_EQ(editor.currentLine(), 1);
    ASSERT_TRUE(bar.findNext());
    EXPECT_EQ(editor.currentLine(), 3);
    ASSERT_TRUE(bar.findNext());
    EXPECT_EQ(editor.currentLine(), 1);
    bar.setCaseSensitive(true);
    EXPECT_FALSE(bar.findNext());
}

}  // namespace
}  // namespace kerf::ui
