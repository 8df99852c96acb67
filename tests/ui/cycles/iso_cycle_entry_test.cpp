// The cycle dialog over a TNC DIN/ISO program: every cycle is written in its ISO form (parameter
// cycles G2xx, SL and cylinder-surface cycles G120-G139, the old cycles as their one G block,
// docs/tnciso.md), the program checks clean as an ISO program, what ISO cannot hold is explained,
// and Edit cycle reads the ISO blocks back.
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextDocument>
#include <map>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/cycles/cycle_registry.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "run_program.h"
#include "test_paths.h"
#include "ui/cycles/cycle_block.h"
#include "ui/cycles/cycle_dialog.h"
#include "ui/cycles/iso_blocks.h"
#include "ui/cycles/program_blocks.h"
#include "ui/editor/program_text_check.h"

namespace kerf::ui {
namespace {

// The dialog of `number` with the typed texts (field index -> text), accepted.
QStringList dialogBlocks(int number, const std::map<int, QString>& typed) {
    CycleDialog dialog(*cycles::findCycle(number), false);
    for (const auto& [field, text] : typed)
        dialog.input(field)->setText(text);
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted)
        << number << ": " << dialog.message().toStdString();
    return dialog.blocks();
}

TEST(IsoCycleEntry, EveryCycleWrittenIntoAnIsoProgramChecksClean) {
    test::testApp();
    // What an operator types where a word has no default (cycle -> field -> text).
    const std::map<int, std::map<int, QString>> typed = {{7, {{0, "+10"}, {1, "+5"}}},
                                                         {8, {{0, "X Y"}}},
                                                         {9, {{0, "1.5"}}},
                                                         {10, {{0, "I45"}}},
                                                         {11, {{0, "0.75"}}},
                                                         {12, {{0, "SUB.H"}}},
                                                         {13, {{0, "90"}}},
                                                         {14, {{0, "1/2"}}},
                                                         {18, {{0, "-20"}, {1, "1.5"}}},
                                                         {19, {{1, "+10"}}},
                                                         {32, {{0, "0.05"}}},
                                                         {225, {{0, "KERF"}}}};
    QStringList blocks;
    for (const cycles::CycleDescriptor* cycle : cycles::allCycles()) {
        if (cycle->number == 26) continue;  // no ISO code (the cycle manual's index)
        const auto it = typed.find(cycle->number);
        const IsoResult iso = isoCycleBlock(
            dialogBlocks(cycle->number, it == typed.end() ? std::map<int, QString>{} : it->second));
        EXPECT_TRUE(iso.error.isEmpty()) << cycle->number << ": " << iso.error.toStdString();
        blocks << iso.block;
    }
    // What the cycles name must exist: cycle 14's contour labels 1 and 2, cycle 12's SUB.H.
    blocks << "G00 G40 G90 Z+100 M30";
    for (const char* label : {"1", "2"}) {
        blocks << QStringLiteral("G98 L%1").arg(label) << "G01 G41 G90 X+0 Y+0 F100"
               << "G01 X+10"
               << "G01 Y+10"
               << "G01 X+0"
               << "G01 Y+0"
               << "G98 L0";
    }
    QString text = "%ALL G71 *\n";
    for (int i = 0; i < blocks.size(); ++i)
        text += QStringLiteral("N%1 ").arg((i + 1) * 10) + blocks[i] + " *\n";
    text += "N99999999 %ALL G71 *\n";
    const std::filesystem::path root = kerf::test::uniqueTempDir("iso_cycle_entry_all");
    writeFileAtomically(root / "SUB.H", "0 BEGIN PGM SUB MM\n1 END PGM SUB MM\n");
    const auto machine = machine::loadMachine("mill");
    ASSERT_TRUE(machine.ok());
    for (const Diagnostic& d : checkProgramText(text.toStdString(), (root / "ALL.I").string(),
                                                program::Dialect::TncIso, *machine, root))
        ADD_FAILURE() << d.format() << "\n" << text.toStdString();
    std::filesystem::remove_all(root);
    // The forms of the cycle manual's index and docs/tnciso.md, from the values typed above.
    for (const char* expected :
         {" G120 CONTOUR DATA\n", " G122 ROUGH-OUT\n", " G139 CYLINDER SURFACE CONTOUR\n",
          " G54 G90 X+10 Y+5 *", " G28 X Y *", " G04 F1.5 *", " G73 G91 H+45 *", " G72 F0.75 *",
          " G39 P01 \"SUB.H\" *", " G36 S90 *", " G37 P01 1 P02 2 *", " G18 P01 -20 P02 +1.5 *",
          " G80 B+10 *", " G62 T0.05 *", " G200 DRILLING\n"})
        EXPECT_TRUE(text.contains(expected)) << expected << "\n" << text.toStdString();
    EXPECT_FALSE(text.contains("CYCL DEF")) << text.toStdString();
}

TEST(IsoCycleEntry, WhatIsoCannotHoldIsExplainedNotWritten) {
    test::testApp();
    EXPECT_TRUE(isoCycleBlock(dialogBlocks(26, {{0, "1.5"}})).error.contains("no ISO form"));
    // Cycle 7 with X absolute and Y incremental: a G54 block is G90 or G91 as a whole.
    EXPECT_TRUE(isoCycleBlock(dialogBlocks(7, {{0, "+10"}, {1, "I-5"}})).error.contains("G91"));
    // Cycle 19's feed and cycle 32's HSC-MODE have no ISO word.
    const IsoResult plane = isoCycleBlock(dialogBlocks(19, {{1, "+10"}, {3, "1000"}}));
    EXPECT_TRUE(plane.block.isEmpty());
    EXPECT_TRUE(plane.error.contains("A B C")) << plane.error.toStdString();
    const IsoResult tolerance = isoCycleBlock(dialogBlocks(32, {{0, "0.05"}, {1, "1"}}));
    EXPECT_TRUE(tolerance.block.isEmpty());
    EXPECT_TRUE(tolerance.error.contains("cycle 32")) << tolerance.error.toStdString();
}

TEST(IsoCycleEntry, EditCycleReadsIsoOldAndSlCyclesBack) {
    test::testApp();
    QPlainTextEdit editor;
    editor.setPlainText(
        "%E G71 *\n"
        "N10 G54 G91 X+5 Y-2 *\n"
        "N20 G120 CONTOUR DATA\n"
        "  Q1=-20 ;MILLING DEPTH\n"
        "  Q2=1 ;TOOL PATH OVERLAP\n"
        "  Q3=+0 ;ALLOWANCE FOR SIDE\n"
        "  Q4=+0 ;ALLOWANCE FOR FLOOR\n"
        "  Q5=+0 ;SURFACE COORDINATE\n"
        "  Q6=2 ;SET-UP CLEARANCE\n"
        "  Q7=+50 ;CLEARANCE HEIGHT\n"
        "  Q8=0 ;ROUNDING RADIUS\n"
        "  Q9=+1 ;ROTATIONAL DIRECTION *\n"
        "N30 G37 P01 3 P02 4 *\n"
        "N99999999 %E G71 *");
    const QTextDocument& document = *editor.document();
    const auto iso = program::Dialect::TncIso;

    const auto shift = cycleDefinitionAt(document, 1, iso);
    ASSERT_TRUE(shift.has_value());
    EXPECT_EQ(shift->first, 1);
    EXPECT_EQ(shift->last, 1);
    const auto readShift = readCycleBlocks(blockTexts(document, *shift, iso));
    ASSERT_TRUE(readShift.has_value());
    EXPECT_EQ(readShift->cycle->number, 7);
    EXPECT_EQ(readShift->values, QStringList({"I+5", "I-2", ""}));

    const auto contour = cycleDefinitionAt(document, 5, iso);  // the cursor on Q3
    ASSERT_TRUE(contour.has_value());
    EXPECT_EQ(contour->first, 2);
    EXPECT_EQ(contour->last, 11);
    const auto readContour = readCycleBlocks(blockTexts(document, *contour, iso));
    ASSERT_TRUE(readContour.has_value());
    EXPECT_EQ(readContour->cycle->number, 20);
    EXPECT_EQ(readContour->values.value(0), "-20");

    const auto labels = cycleDefinitionAt(document, 12, iso);
    ASSERT_TRUE(labels.has_value());
    const auto readLabels = readCycleBlocks(blockTexts(document, *labels, iso));
    ASSERT_TRUE(readLabels.has_value());
    EXPECT_EQ(readLabels->cycle->number, 14);
    EXPECT_EQ(readLabels->values, QStringList({"3/4"}));

    // Z added to the shift: the block keeps its number and stays incremental.
    CycleDialog dialog(*readShift->cycle, false);
    dialog.setValues(readShift->values);
    dialog.input(2)->setText("I-1");
    dialog.accept();
    ASSERT_EQ(dialog.result(), QDialog::Accepted) << dialog.message().toStdString();
    const IsoResult written = isoCycleBlock(dialog.blocks());
    ASSERT_TRUE(written.error.isEmpty()) << written.error.toStdString();
    replaceBlocks(editor, *shift, {written.block}, iso);
    EXPECT_EQ(editor.toPlainText().split('\n').value(1), "N10 G54 G91 X+5 Y-2 Z-1 *");
}

TEST(IsoCycleEntry, AnIsoProgramWithG70IsInch) {
    test::testApp();
    QPlainTextEdit editor;
    editor.setPlainText("%P G70 *\nN99999999 %P G70 *");
    EXPECT_TRUE(programIsInch(*editor.document()));
    editor.setPlainText("%P G71 *\nN99999999 %P G71 *");
    EXPECT_FALSE(programIsInch(*editor.document()));
}

}  // namespace
}  // namespace kerf::ui
