// Path-function and TOOL CALL dialogs, the cycle catalogue and the programming softkeys that
// open them over the editor.
#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QTest>
#include <QTextBlock>
#include <QTimer>
#include <set>

#include <gtest/gtest.h>

#include "core/cycles/cycle_registry.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "run_program.h"
#include "ui/cycles/cycle_catalogue.h"
#include "ui/cycles/cycle_catalogue_dialog.h"
#include "ui/cycles/cycle_dialog.h"
#include "ui/cycles/cycle_help_picture.h"
#include "ui/cycles/path_function_dialog.h"
#include "ui/cycles/programming_softkeys.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_text_check.h"

namespace kerf::ui {
namespace {

void type(PathFunctionDialog& dialog, int field, const QString& text) {
    auto* edit = qobject_cast<QLineEdit*>(dialog.input(field));
    ASSERT_NE(edit, nullptr);
    edit->setText(text);
}

void choose(PathFunctionDialog& dialog, int field, const QString& text) {
    auto* combo = qobject_cast<QComboBox*>(dialog.input(field));
    ASSERT_NE(combo, nullptr);
    combo->setCurrentIndex(combo->findText(text));
}

TEST(PathFunctionDialog, WritesTheBlocksTheParserReads) {
    test::testApp();
    PathFunctionDialog line(PathFunction::Line);  // X Y Z R F M
    type(line, 0, "10");
    type(line, 1, "i-5.5");
    choose(line, 3, "RL");
    type(line, 4, "200");
    type(line, 5, "3 8");
    EXPECT_EQ(line.block(), "L X+10 IY-5.5 RL F200 M3 M8");

    PathFunctionDialog arc(PathFunction::CircleRadius);  // X Y R DR R F M
    type(arc, 0, "40");
    type(arc, 1, "0");
    type(arc, 2, "-20");
    choose(arc, 3, "DR-");
    EXPECT_EQ(arc.block(), "CR X+40 Y+0 R-20 DR-");

    PathFunctionDialog centre(PathFunction::CircleCentre);
    type(centre, 0, "50");
    type(centre, 1, "Q7");
    EXPECT_EQ(centre.block(), "CC X+50 Y+Q7");

    PathFunctionDialog circle(PathFunction::Circle);
    type(circle, 0, "50");
    type(circle, 1, "0");
    choose(circle, 2, "DR+");
    EXPECT_EQ(circle.block(), "C X+50 Y+0 DR+");

    PathFunctionDialog chamfer(PathFunction::Chamfer);
    type(chamfer, 0, "5");
    EXPECT_EQ(chamfer.block(), "CHF 5");

    PathFunctionDialog rounding(PathFunction::Rounding);
    type(rounding, 0, "2.5");
    type(rounding, 1, "100");
    EXPECT_EQ(rounding.block(), "RND R2.5 F100");

    PathFunctionDialog tool(PathFunction::ToolCall);  // tool axis S F DL DR
    type(tool, 0, "3");
    type(tool, 2, "1000");
    type(tool, 4, "-1");
    type(tool, 5, "0.5");
    EXPECT_EQ(tool.block(), "TOOL CALL 3 Z S1000 DL-1 DR+0.5");

    PathFunctionDialog tangent(PathFunction::CircleTangential);
    type(tangent, 0, "20");
    type(tangent, 1, "10");
    EXPECT_EQ(tangent.block(), "CT X+20 Y+10");

    // The blocks in a program the Klartext check accepts (the chamfer between two lines, the
    // tangential arc after a line, as the golden programs write them).
    const QString program =
        "0 BEGIN PGM PATH MM\n1 " + tool.block() + "\n2 L X+0 Y+0 Z+0 R0 FMAX\n3 " + line.block() +
        "\n4 " + chamfer.block() + "\n5 L X+20 Y+20\n6 " + rounding.block() +
        "\n7 L X+40 Y+20\n8 " + arc.block() + "\n9 " + centre.block() + "\n10 " + circle.block() +
        "\n11 L X+10 Y+0\n12 " + tangent.block() + "\n13 L Z+50 R0 FMAX M2\n14 END PGM PATH MM";
    const auto machine = machine::loadMachine("mill");
    ASSERT_TRUE(machine.ok());
    for (const Diagnostic& d : checkProgramText(program.toStdString(), "PATH.H",
                                                program::Dialect::Klartext, *machine, {}))
        ADD_FAILURE() << d.format() << "\n" << program.toStdString();
}

TEST(PathFunctionDialog, RefusesWhatTheBlockCannotHold) {
    test::testApp();
    PathFunctionDialog line(PathFunction::Line);
    line.accept();  // no coordinate at all
    EXPECT_EQ(line.result(), QDialog::Rejected);
    EXPECT_TRUE(line.message().contains("coordinate")) << line.message().toStdString();
    type(line, 0, "1O");  // letter O for a zero
    QTest::keyClick(line.input(0), Qt::Key_Return);
    EXPECT_TRUE(line.message().contains("\"1O\"")) << line.message().toStdString();
    type(line, 0, "10");
    type(line, 4, "fast");
    line.accept();
    EXPECT_TRUE(line.message().contains("FMAX")) << line.message().toStdString();
    type(line, 4, "fmax");
    line.accept();
    EXPECT_EQ(line.result(), QDialog::Accepted) << line.message().toStdString();
    EXPECT_EQ(line.block(), "L X+10 FMAX");

    PathFunctionDialog arc(PathFunction::CircleRadius);
    type(arc, 0, "10");
    type(arc, 2, "0");
    arc.accept();
    EXPECT_TRUE(arc.message().contains("other than 0")) << arc.message().toStdString();
}

TEST(CycleCatalogue, ListsEveryRegistryCycleOnceInTheTncGroups) {
    test::testApp();
    const std::vector<CatalogueSection> sections = cycleCatalogue();
    std::multiset<int> listed;
    for (const CatalogueSection& section : sections) {
        EXPECT_FALSE(section.cycles.empty());
        for (const cycles::CycleDescriptor* cycle : section.cycles)
            listed.insert(cycle->number);
    }
    EXPECT_EQ(listed.size(), cycles::allCycles().size());
    for (const cycles::CycleDescriptor* cycle : cycles::allCycles())
        EXPECT_EQ(listed.count(cycle->number), 1u) << cycle->number;
    // The TNC's order: drilling/thread first, special cycles last.
    ASSERT_GE(sections.size(), 4u);
    EXPECT_EQ(sections.front().group, CatalogueGroup::DrillingThread);
    EXPECT_EQ(sections.back().group, CatalogueGroup::SpecialCycles);
    EXPECT_EQ(catalogueGroup(*cycles::findCycle(262)), CatalogueGroup::DrillingThread);
    EXPECT_EQ(catalogueGroup(*cycles::findCycle(221)), CatalogueGroup::Patterns);
    EXPECT_EQ(catalogueGroup(*cycles::findCycle(10)), CatalogueGroup::CoordinateTransformations);
    EXPECT_EQ(catalogueGroup(*cycles::findCycle(9)), CatalogueGroup::SpecialCycles);
    for (int pocket : {232, 251, 252, 253, 254, 256, 257, 258}) {
        EXPECT_EQ(catalogueGroup(*cycles::findCycle(pocket)), CatalogueGroup::PocketsStudsSlots)
            << pocket;
    }
}

TEST(CycleCatalogueDialog, PicksACycleFromItsGroupOrByNumber) {
    test::testApp();
    CycleCatalogueDialog byList;
    byList.showGroup(0);
    EXPECT_EQ(byList.list()->item(0)->text(), "200 DRILLING");
    byList.list()->setCurrentRow(1);
    byList.accept();
    ASSERT_NE(byList.selectedCycle(), nullptr);
    EXPECT_EQ(byList.selectedCycle()->number, 201);

    CycleCatalogueDialog byNumber;
    QTest::keyClicks(byNumber.numberInput(), "999");
    QTest::keyClick(byNumber.numberInput(), Qt::Key_Return);
    EXPECT_EQ(byNumber.result(), QDialog::Rejected);
    byNumber.numberInput()->setText("221");
    QTest::keyClick(byNumber.numberInput(), Qt::Key_Return);
    ASSERT_NE(byNumber.selectedCycle(), nullptr);
    EXPECT_EQ(byNumber.selectedCycle()->number, 221);
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

TEST(ProgrammingSoftkeys, CyclDefGroupCycleWritesTheDefinitionAtTheCursor) {
    test::testApp();
    ProgramEditor editor;
    editor.setPlainText("0 BEGIN PGM K MM\n1 L X+0 Y+0 R0 FMAX\n2 END PGM K MM");
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(1)));
    std::vector<SoftkeyRow> shown;
    bool back = false;
    SoftkeyPaging paging{[&shown](std::vector<SoftkeyRow> rows) { shown = std::move(rows); },
                         [&back] { back = true; }};
    const auto findKey = [](const std::vector<SoftkeyRow>& rows, const QString& id) {
        for (const SoftkeyRow& row : rows) {
            for (const Softkey& key : row) {
                if (key.id == id) return key.action;
            }
        }
        return std::function<void()>();
    };
    const std::vector<SoftkeyRow> entry = programmingEntryRows(&editor, nullptr, paging);
    findKey(entry, "cyclDef")();
    ASSERT_TRUE(findKey(shown, "cycleGroup0"));  // drilling/thread
    findKey(shown, "cycleGroup0")();
    ASSERT_TRUE(findKey(shown, "cycle203"));
    answerNextDialog<CycleDialog>([](CycleDialog& dialog) {
        dialog.input(1)->setText("-12");  // Q201
        dialog.accept();
    });
    findKey(shown, "cycle203")();
    EXPECT_TRUE(back);  // the normal rows come back after the definition
    const QStringList lines = editor.toPlainText().split('\n');
    ASSERT_GE(lines.size(), 4);
    EXPECT_EQ(lines[2], "2 CYCL DEF 203 UNIVERSAL DRILLING ~");
    EXPECT_TRUE(lines.contains("  Q201=-12     ;DEPTH ~")) << editor.toPlainText().toStdString();
    EXPECT_EQ(lines.last(), "3 END PGM K MM");

    // Path function L after the definition; Esc on a dialog writes nothing.
    answerNextDialog<PathFunctionDialog>([](PathFunctionDialog& dialog) {
        qobject_cast<QLineEdit*>(dialog.input(0))->setText("30");
        dialog.accept();
    });
    findKey(entry, "pathL")();
    EXPECT_TRUE(editor.toPlainText().contains("\n3 L X+30\n4 END PGM K MM"));
    const QString before = editor.toPlainText();
    answerNextDialog<PathFunctionDialog>([](PathFunctionDialog& dialog) { dialog.reject(); });
    findKey(entry, "pathCC")();
    EXPECT_EQ(editor.toPlainText(), before);

    // Edit cycle with the cursor on the definition's Q201 line.
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(4)));
    answerNextDialog<CycleDialog>([](CycleDialog& dialog) {
        EXPECT_EQ(dialog.input(1)->text(), "-12");
        dialog.input(1)->setText("-14");
        dialog.accept();
    });
    findKey(entry, "editCycle")();
    EXPECT_TRUE(editor.toPlainText().contains("  Q201=-14     ;DEPTH ~"));
    EXPECT_FALSE(editor.toPlainText().contains("Q201=-12"));
}

// The same keys over a TNC ISO program write its ISO forms (docs/tnciso.md): "G200 DRILLING" with
// the Q lines, G01/G02 with G90 or G91, G79, numbered "N.. *" before the end block; what has no
// ISO form is explained and not written. The result runs on the ISO front end.
TEST(ProgrammingSoftkeys, OverAnIsoProgramTheDialogsWriteIsoBlocks) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(program::Dialect::TncIso);
    editor.setPlainText(
        "%K G71 *\nN1 G30 G17 X+0 Y+0 Z-20 *\nN2 G31 G90 X+100 Y+100 Z+0 *\n"
        "N3 T1 G17 S2000 *\nN4 G00 G40 G90 X+10 Y+10 Z+50 *\n"
        "N99999999 %K G71 *");
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(4)));
    std::vector<SoftkeyRow> shown;
    SoftkeyPaging paging{[&shown](std::vector<SoftkeyRow> rows) { shown = std::move(rows); },
                         [] {}};
    const auto findKey = [](const std::vector<SoftkeyRow>& rows, const QString& id) {
        for (const SoftkeyRow& row : rows) {
            for (const Softkey& key : row) {
                if (key.id == id) return key.action;
            }
        }
        return std::function<void()>();
    };
    const std::vector<SoftkeyRow> entry = programmingEntryRows(&editor, nullptr, paging);
    findKey(entry, "cyclDef")();
    findKey(shown, "cycleGroup0")();
    ASSERT_TRUE(findKey(shown, "cycle200"));
    answerNextDialog<CycleDialog>([](CycleDialog& dialog) {
        dialog.input(1)->setText("-12");  // Q201
        dialog.accept();
    });
    findKey(shown, "cycle200")();
    QStringList lines = editor.toPlainText().split('\n');
    ASSERT_GE(lines.size(), 8);
    EXPECT_EQ(lines[5], "N5 G200 DRILLING");
    EXPECT_TRUE(lines.contains("  Q201=-12     ;DEPTH")) << editor.toPlainText().toStdString();
    EXPECT_TRUE(lines[lines.size() - 2].endsWith(" *")) << "the cycle block is closed";
    EXPECT_EQ(lines.last(), "N99999999 %K G71 *");

    // The cursor is on the definition: L, then CYCL CALL, go after it.
    answerNextDialog<PathFunctionDialog>([](PathFunctionDialog& dialog) {
        qobject_cast<QLineEdit*>(dialog.input(0))->setText("30");
        qobject_cast<QLineEdit*>(dialog.input(1))->setText("20");
        qobject_cast<QLineEdit*>(dialog.input(4))->setText("300");
        dialog.accept();
    });
    findKey(entry, "pathL")();
    findKey(entry, "cyclCall")();
    EXPECT_TRUE(editor.toPlainText().endsWith(
        "\nN6 G01 G90 X+30 Y+20 F300 *\nN7 G79 *\nN99999999 %K G71 *"))
        << editor.toPlainText().toStdString();
    answerNextDialog<PathFunctionDialog>([](PathFunctionDialog& dialog) {
        qobject_cast<QLineEdit*>(dialog.input(0))->setText("i10");
        qobject_cast<QLineEdit*>(dialog.input(1))->setText("40");
        qobject_cast<QComboBox*>(dialog.input(2))->setCurrentIndex(1);  // DR+
        // Mixed absolute and incremental: the message box that follows explains it.
        answerNextDialog<QMessageBox>([](QMessageBox& box) {
            EXPECT_TRUE(box.text().contains("G91")) << box.text().toStdString();
            box.accept();
        });
        dialog.accept();
    });
    findKey(entry, "pathC")();
    EXPECT_FALSE(editor.toPlainText().contains("G03")) << editor.toPlainText().toStdString();

    // Edit cycle reads the ISO block back and writes it in place with its number.
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(6)));
    answerNextDialog<CycleDialog>([](CycleDialog& dialog) {
        EXPECT_EQ(dialog.input(1)->text(), "-12");
        dialog.input(1)->setText("-14");
        dialog.accept();
    });
    findKey(entry, "editCycle")();
    lines = editor.toPlainText().split('\n');
    EXPECT_EQ(lines[5], "N5 G200 DRILLING");
    EXPECT_TRUE(lines.contains("  Q201=-14     ;DEPTH")) << editor.toPlainText().toStdString();

    // The program the dialogs wrote runs on the ISO front end: the drilling reaches Z-14.
    const test::ProgramRun run = test::runIsoProgram(editor.toPlainText().toStdString());
    EXPECT_TRUE(run.finished);
    EXPECT_TRUE(run.diagnostics.empty())
        << (run.diagnostics.empty() ? "" : run.diagnostics.front().message());
    ASSERT_FALSE(run.feedZ.empty());
    EXPECT_NEAR(*std::min_element(run.feedZ.begin(), run.feedZ.end()), -14.0, 1e-9);

    // Inserted between N1 and N2, the blocks after it move up by the program's step.
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(1)));
    findKey(entry, "cyclCall")();
    lines = editor.toPlainText().split('\n');
    EXPECT_EQ(lines[2], "N2 G79 *");
    EXPECT_EQ(lines[3], "N3 G31 G90 X+100 Y+100 Z+0 *");
    EXPECT_TRUE(lines.contains("N8 G79 *")) << editor.toPlainText().toStdString();
    EXPECT_EQ(lines.last(), "N99999999 %K G71 *");
}

// The old cycles and the SL cycles through the same keys over an ISO program: cycle 10 becomes
// its G73 block, cycle 20 the G120 block (the cycle manual's index); the program runs with them.
TEST(ProgrammingSoftkeys, OverAnIsoProgramOldAndSlCyclesWriteTheirGFunctions) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(program::Dialect::TncIso);
    editor.setPlainText(
        "%R G71 *\nN10 G30 G17 X+0 Y+0 Z-20 *\nN20 G31 G90 X+100 Y+100 Z+0 *\n"
        "N30 T1 G17 S2000 *\nN40 G00 G40 G90 X+0 Y+0 Z+50 *\nN99999999 %R G71 *");
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(4)));
    std::vector<SoftkeyRow> shown;
    SoftkeyPaging paging{[&shown](std::vector<SoftkeyRow> rows) { shown = std::move(rows); },
                         [] {}};
    const auto findKey = [](const std::vector<SoftkeyRow>& rows, const QString& id) {
        for (const SoftkeyRow& row : rows) {
            for (const Softkey& key : row) {
                if (key.id == id) return key.action;
            }
        }
        return std::function<void()>();
    };
    const std::vector<SoftkeyRow> entry = programmingEntryRows(&editor, nullptr, paging);
    // The group that holds `cycle`, opened from CYCL DEF.
    const auto openGroupOf = [&](int cycle) {
        for (int group = 0; group < 6; ++group) {
            findKey(entry, "cyclDef")();
            const auto key = findKey(shown, QStringLiteral("cycleGroup%1").arg(group));
            if (!key) break;
            key();
            if (findKey(shown, QStringLiteral("cycle%1").arg(cycle))) return true;
        }
        return false;
    };
    ASSERT_TRUE(openGroupOf(10));
    answerNextDialog<CycleDialog>([](CycleDialog& dialog) {
        dialog.input(0)->setText("I90");
        dialog.accept();
    });
    findKey(shown, "cycle10")();
    ASSERT_TRUE(openGroupOf(20));
    answerNextDialog<CycleDialog>([](CycleDialog& dialog) {
        dialog.input(0)->setText("-6");  // Q1 milling depth
        dialog.accept();
    });
    findKey(shown, "cycle20")();
    const QStringList lines = editor.toPlainText().split('\n');
    EXPECT_EQ(lines.value(5), "N50 G73 G91 H+90 *") << editor.toPlainText().toStdString();
    EXPECT_EQ(lines.value(6), "N60 G120 CONTOUR DATA");
    EXPECT_EQ(lines.value(7), "  Q1=-6        ;MILLING DEPTH");
    EXPECT_EQ(lines.last(), "N99999999 %R G71 *");

    // The rotation is in force when the program runs: X+10 after a 90 degree turn is Y+10.
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(5)));
    answerNextDialog<PathFunctionDialog>([](PathFunctionDialog& dialog) {
        type(dialog, 0, "10");
        type(dialog, 2, "-1");
        type(dialog, 4, "100");
        dialog.accept();
    });
    findKey(entry, "pathL")();
    EXPECT_EQ(editor.toPlainText().split('\n').value(6), "N60 G01 G90 X+10 Z-1 F100 *");
    EXPECT_EQ(editor.toPlainText().split('\n').value(7), "N70 G120 CONTOUR DATA");
    const test::ProgramRun run = test::runIsoProgram(editor.toPlainText().toStdString());
    EXPECT_TRUE(run.finished);
    EXPECT_TRUE(run.diagnostics.empty())
        << (run.diagnostics.empty() ? "" : run.diagnostics.front().format());
    ASSERT_EQ(run.feedZ.size(), 1u);
    EXPECT_NEAR(run.feedZ.front(), -1.0, 1e-9);
    EXPECT_NEAR(run.feedXY.front()[0], 0.0, 1e-9);
    EXPECT_NEAR(run.feedXY.front()[1], 10.0, 1e-9);
}

}  // namespace
}  // namespace kerf::ui

namespace kerf::ui {
namespace {

// Pictures for the documentation and for looking at the screens (saved in the test's build
// folder): the catalogue, the drilling dialog on Q201 and the pattern dialog on Q247.
TEST(CycleScreens, SavesScreenshotsOfTheCatalogueAndTheDialogs) {
    test::testApp();
    CycleCatalogueDialog catalogue;
    catalogue.resize(1000, 600);
    catalogue.showGroup(0);
    const QImage cataloguePicture = catalogue.grab().toImage();
    EXPECT_TRUE(cataloguePicture.save("cycle_catalogue.png"));

    CycleDialog drilling(*cycles::findCycle(200), false);
    drilling.resize(1280, 720);
    drilling.setCurrentField(1);
    EXPECT_TRUE(drilling.grab().toImage().save("cycle_dialog_200.png"));

    CycleDialog pattern(*cycles::findCycle(220), false);
    pattern.resize(1280, 720);
    pattern.setCurrentField(6);
    EXPECT_TRUE(pattern.grab().toImage().save("cycle_dialog_220.png"));

    PathFunctionDialog line(PathFunction::Line);
    line.resize(900, 500);
    EXPECT_TRUE(line.grab().toImage().save("path_dialog_l.png"));
    EXPECT_EQ(cataloguePicture.width(), 1000);
    // One help picture of every kind, on a parameter it highlights.
    const std::pair<int, int> pictures[] = {{7, 0},   {10, 0},  {225, 0}, {232, 4},
                                            {221, 5}, {262, 2}, {32, 0},  {18, 0},
                                            {9, 0},   {13, 0},  {251, 1}};
    for (const auto& [number, field] : pictures) {
        CycleDialog dialog(*cycles::findCycle(number), false);
        dialog.resize(1280, 720);
        dialog.setCurrentField(field);
        EXPECT_TRUE(dialog.picture()->grab().toImage().save(
            QStringLiteral("cycle_help_%1.png").arg(number)));
    }
}

}  // namespace
}  // namespace kerf::ui
