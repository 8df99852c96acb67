// SPEC FCT (docs/hmi.md, "Special functions"): the PLANE, TCPM and program-call dialogs write
// the blocks as the TNC writes them, in a conversational and in a TNC ISO program, and what they
// write passes the check that runs the program (task::checkByRunning, as `kerf check`) on the
// five-axis mill.
#include "ui/cycles/special_function.h"

#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QTest>
#include <QTextBlock>
#include <QTimer>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "core/task/dry_run.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/cycles/program_blocks.h"
#include "ui/cycles/programming_softkeys.h"
#include "ui/cycles/special_function_dialog.h"
#include "ui/editor/program_editor.h"

namespace kerf::ui {
namespace {

using SF = SpecialFunction;

// The dialog with `values` typed (combo boxes take their text), accepted: the block, or the
// refusal message with a leading '!'.
QString written(SF function, const QStringList& values,
                program::Dialect dialect = program::Dialect::Klartext) {
    SpecialFunctionDialog dialog(function);
    dialog.setValues(values);
    dialog.accept();
    if (dialog.result() != QDialog::Accepted) return QLatin1Char('!') + dialog.message();
    return writeSpecialFunction(function, dialog.values(), dialect);
}

TEST(SpecialFunction, DialogsWriteTheBlocksAsTheTncWritesThem) {
    test::testApp();
    EXPECT_EQ(
        written(SF::PlaneSpatial, {"0", "45", "0", "TURN", "MAX", "", "FMAX", "SEQ+", "TABLE ROT"}),
        "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN MB MAX FMAX SEQ+ TABLE ROT");
    EXPECT_EQ(written(SF::PlaneProjected, {"10", "-20.5", "q3", "STAY"}),
              "PLANE PROJECTED PROPR+10 PROMIN-20.5 ROT+Q3 STAY");
    EXPECT_EQ(written(SF::PlaneEuler, {"0", "30", "0", "MOVE", "50", "20", "1000"}),
              "PLANE EULER EULPR+0 EULNU+30 EULROT+0 MOVE MB50 DIST20 F1000");
    EXPECT_EQ(written(SF::PlaneVector, {"1", "0", "0", "0", "0", "1", "STAY", "", "", "", "SEQ-"}),
              "PLANE VECTOR BX+1 BY+0 BZ+0 NX+0 NY+0 NZ+1 STAY SEQ-");
    EXPECT_EQ(written(SF::PlanePoints, {"0", "0", "0", "10", "0", "0", "0", "10", "0", "STAY"}),
              "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+10 P2Y+0 P2Z+0 P3X+0 P3Y+10 P3Z+0 STAY");
    EXPECT_EQ(written(SF::PlaneRelative, {"SPB", "-15", "TURN", "", "", "500"}),
              "PLANE RELATIV SPB-15 TURN F500");
    EXPECT_EQ(written(SF::PlaneAxial, {"", "30", "", "TURN", "", "", "FMAX"}),
              "PLANE AXIAL B+30 TURN FMAX");
    EXPECT_EQ(written(SF::PlaneReset, {"STAY"}), "PLANE RESET STAY");
    EXPECT_EQ(written(SF::Tcpm, {"F TCP", "AXIS POS", "PATHCTRL AXIS", "REFPNT TIP-TIP"}),
              "FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS REFPNT TIP-TIP");
    EXPECT_EQ(written(SF::Tcpm, {"F TCP", "", "", ""}), "FUNCTION TCPM F TCP");
    EXPECT_EQ(written(SF::M128, {"1000"}), "M128 F1000");
    EXPECT_EQ(written(SF::M128, {""}), "M128");
    EXPECT_EQ(written(SF::SelectProgram, {"TNC:\\PARTS\\SUB.H"}), "SEL PGM \"TNC:\\PARTS\\SUB.H\"");
    EXPECT_EQ(written(SF::CallProgram, {"SUB"}), "CALL PGM SUB");
    // ISO writes the same words inside its block, except the program call "%NAME".
    EXPECT_EQ(written(SF::CallProgram, {"SUB"}, program::Dialect::TncIso), "%SUB");
    EXPECT_EQ(written(SF::PlaneReset, {"TURN", "", "", "FMAX"}, program::Dialect::TncIso),
              "PLANE RESET TURN FMAX");
    // The functions without words have no dialog.
    for (SF function : {SF::ResetTcpm, SF::M129, SF::CallSelectedProgram})
        EXPECT_TRUE(specialFields(function).empty());
    EXPECT_EQ(writeSpecialFunction(SF::CallSelectedProgram, {}, program::Dialect::TncIso),
              "CALL SELECTED PGM");
}

TEST(SpecialFunction, RefusedEntriesKeepTheDialogOpenWithTheReason) {
    test::testApp();
    // STAY moves nothing; DIST is MOVE's; AXIAL needs an angle; an angle is a number.
    EXPECT_TRUE(written(SF::PlaneSpatial, {"0", "45", "0", "STAY", "", "", "FMAX"})
                    .startsWith("!STAY moves nothing"));
    EXPECT_TRUE(
        written(SF::PlaneSpatial, {"0", "45", "0", "TURN", "", "20"}).startsWith("!DIST belongs"));
    EXPECT_TRUE(written(SF::PlaneAxial, {"", "", "", "TURN"}).startsWith("!PLANE AXIAL"));
    EXPECT_EQ(written(SF::PlaneSpatial, {"0", "x", "0", "TURN"}),
              "!SPB: \"x\" is not allowed here");
    EXPECT_TRUE(written(SF::PlaneSpatial, {"0", "", "0", "TURN"}).startsWith("!SPB: enter"));
    EXPECT_TRUE(written(SF::CallProgram, {"MY PART"}).startsWith("!"));  // a blank
    EXPECT_TRUE(written(SF::PlaneEuler, {"0", "30", "0", "MOVE", "-5"}).startsWith("!MB"));

    // Enter checks the field before it moves on.
    SpecialFunctionDialog dialog(SF::PlaneSpatial);
    auto* spa = qobject_cast<QLineEdit*>(dialog.input(0));
    spa->setText("4x");
    QTest::keyClick(spa, Qt::Key_Return);
    EXPECT_EQ(dialog.message(), "SPA: \"4x\" is not allowed here");
    spa->setText("+4");
    QTest::keyClick(spa, Qt::Key_Return);
    EXPECT_TRUE(dialog.message().isEmpty());
}

// Every function, written by the SPEC FCT keys into a program of each dialect, passes the check
// that runs the program on the five-axis mill; the program call reaches SUB (its M3 is seen in
// neither check error).
TEST(SpecialFunction, EveryFunctionWrittenIntoAProgramPassesTheRunningCheck) {
    test::testApp();
    const std::vector<std::pair<SF, QStringList>> entries = {
        {SF::PlaneSpatial, {"0", "45", "0", "TURN", "MAX", "", "FMAX", "SEQ+", "TABLE ROT"}},
        {SF::PlaneReset, {"TURN", "MAX", "", "FMAX"}},
        {SF::PlaneProjected, {"0", "30", "0", "TURN", "", "", "FMAX"}},
        {SF::PlaneRelative, {"SPB", "10", "MOVE", "", "50", "1000"}},
        {SF::PlaneEuler, {"0", "20", "0", "TURN", "", "", "FMAX"}},
        {SF::PlaneVector, {"1", "0", "0", "0", "0", "1", "TURN", "", "", "FMAX"}},
        {SF::PlanePoints, {"0", "0", "0", "10", "0", "0", "0", "10", "0", "TURN", "", "", "FMAX"}},
        {SF::PlaneAxial, {"", "30", "", "TURN", "", "", "FMAX"}},
        {SF::PlaneReset, {"TURN", "", "", "FMAX"}},
        {SF::Tcpm, {"F TCP", "AXIS POS", "PATHCTRL AXIS", "REFPNT TIP-TIP"}},
        {SF::ResetTcpm, {}},
        {SF::M128, {"1000"}},
        {SF::M129, {}},
        {SF::SelectProgram, {"SUB"}},
        {SF::CallSelectedProgram, {}},
        {SF::CallProgram, {"SUB"}},
    };
    const std::filesystem::path root = kerf::test::uniqueTempDir("special_function_run");
    ASSERT_FALSE(
        writeFileAtomically(root / "SUB.H", "0 BEGIN PGM SUB MM\n1 END PGM SUB MM\n").has_value());
    const auto mill5 = machine::loadMachine("mill5");
    ASSERT_TRUE(mill5.ok());
    for (const auto dialect : {program::Dialect::Klartext, program::Dialect::TncIso}) {
        const bool iso = dialect == program::Dialect::TncIso;
        ProgramEditor editor;
        editor.setDialect(dialect);
        editor.setPlainText(iso ? "%P G71 *\nN1 G30 G17 X-50 Y-50 Z-20 *\n"
                                  "N2 G31 G90 X+50 Y+50 Z+0 *\nN3 T1 G17 S2000 *\n"
                                  "N4 G00 G40 G90 X+0 Y+0 Z+100 *\nN99999999 %P G71 *"
                                : "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X-50 Y-50 Z-20\n"
                                  "2 BLK FORM 0.2 X+50 Y+50 Z+0\n3 TOOL CALL 1 Z S2000\n"
                                  "4 L X+0 Y+0 Z+100 R0 FMAX\n5 END PGM P MM");
        editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(4)));
        for (const auto& [function, values] : entries) {
            ASSERT_FALSE(checkSpecialFunction(function, values).has_value())
                << specialFunctionTitle(function).toStdString();
            insertBlocks(editor, {writeSpecialFunction(function, values, dialect)}, dialect);
        }
        task::ProgramRequest request;
        request.path = root / (iso ? "P.I" : "P.H");
        request.ncRoot = root;
        request.text = editor.toPlainText().toStdString();
        const task::RunCheck check = task::checkByRunning(*mill5, request);
        EXPECT_FALSE(hasErrors(check.diagnostics)) << editor.toPlainText().toStdString() << "\n"
                                                   << check.diagnostics.back().format();
        if (iso) {
            EXPECT_TRUE(editor.toPlainText().contains("N19 CALL SELECTED PGM *\nN20 %SUB *"))
                << editor.toPlainText().toStdString();
        } else {
            EXPECT_TRUE(
                editor.toPlainText().contains("\n18 SEL PGM \"SUB\"\n19 CALL SELECTED "
                                              "PGM\n20 CALL PGM SUB\n21 END PGM P MM"))
                << editor.toPlainText().toStdString();
        }
    }
}

// Finishes the modal dialog that the softkey opens, once the event loop runs it.
template <typename Dialog, typename Fill>
void answerNextDialog(Fill fill) {
    QTimer::singleShot(0, [fill] {
        auto* dialog = qobject_cast<Dialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        fill(*dialog);
    });
}

std::function<void()> findKey(const std::vector<SoftkeyRow>& rows, const QString& id) {
    for (const SoftkeyRow& row : rows)
        for (const Softkey& key : row)
            if (key.id == id) return key.action;
    return {};
}

// SPEC FCT -> PLANE -> SPATIAL opens the dialog and writes the ISO block after the cursor's
// block (numbered by the program's step, 1 with a single numbered block); the
// normal rows come back after it.
TEST(SpecialFunction, SpecFctPlaneSpatialWritesIntoAnIsoProgram) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(program::Dialect::TncIso);
    editor.setPlainText("%K G71 *\nN10 G00 G40 G90 Z+100 *\nN99999999 %K G71 *");
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(1)));
    std::vector<SoftkeyRow> shown;
    bool back = false;
    SoftkeyPaging paging{[&shown](std::vector<SoftkeyRow> rows) { shown = std::move(rows); },
                         [&back] { back = true; }};
    const std::vector<SoftkeyRow> entry = programmingEntryRows(&editor, nullptr, paging);
    ASSERT_TRUE(findKey(entry, "specFct"));
    findKey(entry, "specFct")();
    ASSERT_TRUE(findKey(shown, "plane"));
    ASSERT_TRUE(findKey(shown, "callPgm"));
    findKey(shown, "plane")();
    ASSERT_EQ(shown.front().size(), 8u);  // the eight forms of the TNC 320
    answerNextDialog<SpecialFunctionDialog>([](SpecialFunctionDialog& dialog) {
        ASSERT_EQ(dialog.fieldCount(), 9);
        qobject_cast<QLineEdit*>(dialog.input(0))->setText("0");
        qobject_cast<QLineEdit*>(dialog.input(1))->setText("45");
        qobject_cast<QLineEdit*>(dialog.input(2))->setText("0");
        qobject_cast<QComboBox*>(dialog.input(3))->setCurrentText("TURN");
        qobject_cast<QLineEdit*>(dialog.input(6))->setText("fmax");
        dialog.accept();
    });
    findKey(shown, "planeSpatial")();
    EXPECT_TRUE(back);
    EXPECT_EQ(editor.toPlainText().toStdString(),
              "%K G71 *\nN10 G00 G40 G90 Z+100 *\nN11 PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN "
              "FMAX *\nN99999999 %K G71 *");
}

}  // namespace
}  // namespace kerf::ui
