// Writing and editing cycle definitions through the cycle dialog: the text it writes, the
// refusals, the round trip of an existing CYCL DEF, the help picture and the language.
#include "ui/cycles/cycle_dialog.h"

#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTest>
#include <QTextBlock>
#include <QTranslator>
#include <map>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/cycles/cycle_registry.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "run_program.h"
#include "test_paths.h"
#include "ui/cycles/cycle_block.h"
#include "ui/cycles/cycle_help_picture.h"
#include "ui/cycles/parameter_comments.h"
#include "ui/cycles/program_blocks.h"
#include "ui/editor/program_text_check.h"

namespace kerf::ui {
namespace {

const QString kProgram = QStringLiteral(
    "0 BEGIN PGM DRILL MM\n"
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
    "2 BLK FORM 0.2 X+100 Y+100 Z+0\n"
    "3 TOOL CALL 1 Z S3000\n"
    "4 L X+50 Y+50 Z+50 R0 FMAX M3\n"
    "5 END PGM DRILL MM");

// Types the spec's example values of cycle 200 (spec 2, lines 1636-1649) into the dialog the
// way an operator does: select the field, type, Enter.
void typeDrillingValues(CycleDialog& dialog) {
    const QStringList typed = {"2", "-15", "250", "5", "0", "20", "100", "0.1", "0"};
    ASSERT_EQ(dialog.fieldCount(), typed.size());
    for (int i = 0; i < dialog.fieldCount(); ++i) {
        ASSERT_EQ(dialog.currentField(), i);
        QLineEdit* input = dialog.input(i);
        input->selectAll();
        QTest::keyClicks(input, typed[i]);
        QTest::keyClick(input, Qt::Key_Return);
    }
}

DiagnosticList check(const QString& text) {
    const auto machine = machine::loadMachine("mill");
    EXPECT_TRUE(machine.ok());
    return checkProgramText(text.toStdString(), "DRILL.H", program::Dialect::Klartext, *machine,
                            {});
}

TEST(CycleDialog, WritesTheDrillingCycleAtTheCursorAndTheProgramChecksClean) {
    test::testApp();
    QPlainTextEdit editor;
    editor.setPlainText(kProgram);
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(4)));

    CycleDialog dialog(*cycles::findCycle(200), false);
    typeDrillingValues(dialog);
    ASSERT_EQ(dialog.result(), QDialog::Accepted) << dialog.message().toStdString();
    insertBlocks(editor, dialog.blocks());
    insertBlocks(editor, {QStringLiteral("CYCL CALL")});

    const QString expected = QStringLiteral(
        "0 BEGIN PGM DRILL MM\n"
        "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
        "2 BLK FORM 0.2 X+100 Y+100 Z+0\n"
        "3 TOOL CALL 1 Z S3000\n"
        "4 L X+50 Y+50 Z+50 R0 FMAX M3\n"
        "5 CYCL DEF 200 DRILLING ~\n"
        "  Q200=+2      ;SET-UP CLEARANCE ~\n"
        "  Q201=-15     ;DEPTH ~\n"
        "  Q206=+250    ;FEED RATE FOR PLNGNG ~\n"
        "  Q202=+5      ;PLUNGING DEPTH ~\n"
        "  Q210=+0      ;DWELL TIME AT TOP ~\n"
        "  Q203=+20     ;SURFACE COORDINATE ~\n"
        "  Q204=+100    ;2ND SET-UP CLEARANCE ~\n"
        "  Q211=+0.1    ;DWELL TIME AT DEPTH ~\n"
        "  Q395=+0      ;DEPTH REFERENCE\n"
        "6 CYCL CALL\n"
        "7 END PGM DRILL MM");
    EXPECT_EQ(editor.toPlainText().toStdString(), expected.toStdString());
    const DiagnosticList diagnostics = check(editor.toPlainText());
    for (const Diagnostic& d : diagnostics)
        ADD_FAILURE() << d.format();
    // Run on the simulated mill: surface Z+20, depth 15 in infeeds of 5 gives feed moves to
    // Z+15, Z+10 and Z+5 (spec cycle 200, execution steps 2-5).
    const test::ProgramRun run = test::runKlartextProgram(editor.toPlainText().toStdString());
    for (const Diagnostic& d : run.diagnostics)
        ADD_FAILURE() << d.format();
    EXPECT_TRUE(run.finished);
    ASSERT_EQ(run.feedZ.size(), 3u);
    EXPECT_NEAR(run.feedZ[0], 15.0, 1e-9);
    EXPECT_NEAR(run.feedZ[1], 10.0, 1e-9);
    EXPECT_NEAR(run.feedZ[2], 5.0, 1e-9);

    // One undo step takes the CYCL CALL out again, a second one the definition.
    editor.undo();
    editor.undo();
    EXPECT_EQ(editor.toPlainText().toStdString(), kProgram.toStdString());
}

TEST(CycleDialog, RefusesOutOfRangeWholeNumberAndKeywordErrorsWithAMessage) {
    test::testApp();
    CycleDialog dialog(*cycles::findCycle(200), false);
    QLineEdit* clearance = dialog.input(0);
    clearance->setText("-1");
    QTest::keyClick(clearance, Qt::Key_Return);
    EXPECT_EQ(dialog.currentField(), 0);  // stays on the refused field
    EXPECT_TRUE(dialog.message().contains("Q200")) << dialog.message().toStdString();
    EXPECT_TRUE(dialog.message().contains("outside")) << dialog.message().toStdString();

    clearance->setText("PREDEF");  // Q200 may take the GLOBAL DEF value
    QTest::keyClick(clearance, Qt::Key_Return);
    EXPECT_EQ(dialog.currentField(), 1);
    EXPECT_TRUE(dialog.message().isEmpty());

    dialog.input(2)->setText("FMAX");  // Q206 allows FAUTO and FU, not FMAX
    dialog.input(8)->setText("0.5");   // Q395 is 0 or 1
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Rejected);
    EXPECT_TRUE(dialog.message().contains("FMAX")) << dialog.message().toStdString();
    dialog.input(2)->setText("FAUTO");
    dialog.accept();
    EXPECT_TRUE(dialog.message().contains("whole number")) << dialog.message().toStdString();
    dialog.input(8)->setText("1");
    dialog.input(1)->setText("abc");
    dialog.accept();
    EXPECT_TRUE(dialog.message().contains("not a number")) << dialog.message().toStdString();
    dialog.input(1)->setText("-10");
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted) << dialog.message().toStdString();
}

TEST(CycleDialog, EscapeCancels) {
    test::testApp();
    CycleDialog dialog(*cycles::findCycle(200), false);
    dialog.show();
    QTest::keyClick(dialog.input(0), Qt::Key_Escape);
    EXPECT_EQ(dialog.result(), QDialog::Rejected);
    EXPECT_FALSE(dialog.isVisible());
}

TEST(CycleDialog, FieldsAndButtonsAreTouchTargets) {
    test::testApp();
    CycleDialog dialog(*cycles::findCycle(205), false);
    dialog.resize(1280, 720);
    dialog.show();
    for (const QWidget* widget : dialog.findChildren<QLineEdit*>())
        EXPECT_GE(widget->height(), 48) << widget->objectName().toStdString();
    for (const QWidget* widget : dialog.findChildren<QPushButton*>())
        EXPECT_GE(widget->height(), 48) << widget->objectName().toStdString();
    EXPECT_FALSE(dialog.findChildren<QPushButton*>().isEmpty());
}

TEST(CycleDialog, EditingAnExistingDefinitionRoundTripsItsValues) {
    test::testApp();
    // The older format without '~' (spec 1.4), as the golden programs write it.
    QPlainTextEdit editor;
    editor.setPlainText(
        "0 BEGIN PGM P MM\n"
        "1 CYCL DEF 240 CENTERING\n"
        "  Q200=2 ;SET-UP CLEARANCE\n"
        "  Q343=1 ;SELECT DIA./DEPTH\n"
        "  Q201=-2 ;DEPTH\n"
        "  Q344=-10 ;DIAMETER\n"
        "  Q206=FAUTO ;FEED RATE FOR PLNGNG\n"
        "  Q211=0 ;DWELL TIME AT DEPTH\n"
        "  Q203=+Q5 ;SURFACE COORDINATE\n"
        "  Q204=PREDEF ;2ND SET-UP CLEARANCE\n"
        "2 CYCL CALL\n"
        "3 END PGM P MM");
    const auto range = cycleDefinitionAt(*editor.document(), 4);  // cursor on Q201
    ASSERT_TRUE(range.has_value());
    EXPECT_EQ(range->first, 1);
    EXPECT_EQ(range->last, 9);
    const auto read = readCycleBlocks(blockTexts(*editor.document(), *range));
    ASSERT_TRUE(read.has_value());
    ASSERT_EQ(read->cycle->number, 240);

    CycleDialog dialog(*read->cycle, false);
    dialog.setValues(read->values);
    const QStringList expected = {"2", "1", "-2", "-10", "FAUTO", "0", "+Q5", "PREDEF"};
    EXPECT_EQ(dialog.values(), expected);
    dialog.input(2)->setText("-4");
    dialog.accept();
    ASSERT_EQ(dialog.result(), QDialog::Accepted) << dialog.message().toStdString();
    replaceBlocks(editor, *range, dialog.blocks());
    const QStringList lines = editor.toPlainText().split('\n');
    EXPECT_EQ(lines[1], "1 CYCL DEF 240 CENTERING ~");
    EXPECT_EQ(lines[4], "  Q201=-4      ;DEPTH ~");
    EXPECT_EQ(lines[6], "  Q206=FAUTO   ;FEED RATE FOR PLNGNG ~");
    EXPECT_EQ(lines[8], "  Q203=+Q5     ;SURFACE COORDINATE ~");
    EXPECT_EQ(lines[9], "  Q204=PREDEF  ;2ND SET-UP CLEARANCE");
    EXPECT_EQ(lines[10], "2 CYCL CALL");
}

TEST(CycleDialog, OldStyleCyclesRoundTripTheirSubBlocks) {
    test::testApp();
    QPlainTextEdit editor;
    editor.setPlainText(
        "0 BEGIN PGM S MM\n"
        "1 CYCL DEF 7.0 DATUM SHIFT\n"
        "2 CYCL DEF 7.1 X+60\n"
        "3 CYCL DEF 7.2 IY-40\n"
        "4 CYCL DEF 32.0 TOLERANCE\n"
        "5 CYCL DEF 32.1 T0.05\n"
        "6 CYCL DEF 32.2 HSC-MODE:1 TA5\n"
        "7 END PGM S MM");
    const auto shift = cycleDefinitionAt(*editor.document(), 3);
    ASSERT_TRUE(shift.has_value());
    EXPECT_EQ(shift->first, 1);
    EXPECT_EQ(shift->last, 3);
    const auto readShift = readCycleBlocks(blockTexts(*editor.document(), *shift));
    ASSERT_TRUE(readShift.has_value());
    EXPECT_EQ(readShift->values, QStringList({"+60", "I-40", ""}));

    const auto tolerance = cycleDefinitionAt(*editor.document(), 4);
    ASSERT_TRUE(tolerance.has_value());
    EXPECT_EQ(tolerance->last, 6);
    const auto readTolerance = readCycleBlocks(blockTexts(*editor.document(), *tolerance));
    ASSERT_TRUE(readTolerance.has_value());
    EXPECT_EQ(readTolerance->values, QStringList({"0.05", "1", "5"}));

    // Z added to the shift: one more sub-block, the blocks after it renumbered.
    CycleDialog dialog(*readShift->cycle, false);
    dialog.setValues(readShift->values);
    dialog.input(2)->setText("-5");
    dialog.accept();
    ASSERT_EQ(dialog.result(), QDialog::Accepted) << dialog.message().toStdString();
    replaceBlocks(editor, *shift, dialog.blocks());
    EXPECT_EQ(editor.toPlainText().toStdString(),
              "0 BEGIN PGM S MM\n"
              "1 CYCL DEF 7.0 DATUM SHIFT\n"
              "2 CYCL DEF 7.1 X+60\n"
              "3 CYCL DEF 7.2 IY-40\n"
              "4 CYCL DEF 7.3 Z-5\n"
              "5 CYCL DEF 32.0 TOLERANCE\n"
              "6 CYCL DEF 32.1 T0.05\n"
              "7 CYCL DEF 32.2 HSC-MODE:1 TA5\n"
              "8 END PGM S MM");
    EXPECT_TRUE(check(editor.toPlainText()).empty());
}

TEST(CycleDialog, InchProgramsAskForInchAndScaleTheDefaults) {
    test::testApp();
    QPlainTextEdit editor;
    editor.setPlainText("0 BEGIN PGM P INCH\n1 END PGM P INCH");
    ASSERT_TRUE(programIsInch(*editor.document()));
    CycleDialog dialog(*cycles::findCycle(200), programIsInch(*editor.document()));
    // 2 mm set-up clearance = 0.0787 inch; 150 mm/min = 5.9055 inch/min.
    EXPECT_EQ(dialog.input(0)->text(), "0.0787");
    EXPECT_EQ(dialog.input(2)->text(), "5.9055");
    dialog.input(0)->setText("4000");  // 99999.9999 mm = 3937.00787 inch
    dialog.accept();
    EXPECT_TRUE(dialog.message().contains("3937.0079")) << dialog.message().toStdString();
}

TEST(ParameterComments, EveryQParameterOfTheRegistryHasTheSpecComment) {
    test::testApp();
    for (const cycles::CycleDescriptor* cycle : cycles::allCycles()) {
        if (cycle->oldStyle) continue;
        for (const cycles::ParameterDescriptor& p : cycle->parameters) {
            EXPECT_TRUE(hasSpecComment(cycle->number, p.q)) << cycle->number << " Q" << p.q;
            EXPECT_LE(parameterComment(cycle->number, p).size(), kMaxCommentLength);
        }
    }
    // Cycle-specific names where the TNC has them (spec: 206 "DEPTH OF THREAD").
    EXPECT_EQ(parameterComment(206, *cycles::findCycle(206)->parameter(201)), "DEPTH OF THREAD");
    EXPECT_EQ(parameterComment(200, *cycles::findCycle(200)->parameter(201)), "DEPTH");
}

TEST(CycleDialog, EveryCycleWrittenWithItsDefaultsOrSampleValuesChecksClean) {
    test::testApp();
    // Old-style words without a default get a value an operator would type.
    const std::map<std::pair<int, int>, QString> typed = {
        {{7, 0}, "+10"},  {{7, 1}, "I-5"},  {{8, 0}, "X Y"},  {{10, 0}, "I45"}, {{12, 0}, "SUB.H"},
        {{14, 0}, "1/2"}, {{19, 1}, "+10"}, {{26, 0}, "1.5"}, {{26, 3}, "+20"}, {{225, 0}, "KERF"}};
    QStringList program{"BEGIN PGM ALL MM"};
    for (const cycles::CycleDescriptor* cycle : cycles::allCycles()) {
        CycleDialog dialog(*cycle, false);
        for (const auto& [key, value] : typed) {
            if (key.first == cycle->number) dialog.input(key.second)->setText(value);
        }
        dialog.accept();
        ASSERT_EQ(dialog.result(), QDialog::Accepted)
            << cycle->number << ": " << dialog.message().toStdString();
        program << dialog.blocks();
    }
    // What the cycles name must exist: cycle 14's contour labels 1 and 2, cycle 12's SUB.H.
    program << "L Z+100 R0 FMAX M30";
    for (const char* label : {"1", "2"}) {
        program << QStringLiteral("LBL %1").arg(label) << "L X+0 Y+0 RL"
                << "L X+10"
                << "L Y+10"
                << "L X+0"
                << "L Y+0"
                << "LBL 0";
    }
    program << "END PGM ALL MM";
    QString text;
    for (int i = 0; i < program.size(); ++i)
        text += QString::number(i) + ' ' + program[i] + '\n';
    const std::filesystem::path root = kerf::test::uniqueTempDir("cycle_dialog_all");
    writeFileAtomically(root / "SUB.H", "0 BEGIN PGM SUB MM\n1 END PGM SUB MM\n");
    const auto machine = machine::loadMachine("mill");
    ASSERT_TRUE(machine.ok());
    for (const Diagnostic& d : checkProgramText(text.toStdString(), (root / "ALL.H").string(),
                                                program::Dialect::Klartext, *machine, root))
        ADD_FAILURE() << d.format() << "\n" << text.toStdString();
    std::filesystem::remove_all(root);
    // Spot checks of the old-style syntax (spec 9 and 10).
    EXPECT_TRUE(text.contains("CYCL DEF 7.1 X+10\n")) << text.toStdString();
    EXPECT_TRUE(text.contains("CYCL DEF 7.2 IY-5\n"));
    EXPECT_TRUE(text.contains("CYCL DEF 8.1 X Y\n"));
    EXPECT_TRUE(text.contains("CYCL DEF 10.1 IROT+45\n"));
    EXPECT_TRUE(text.contains("CYCL DEF 11.1 SCL 1\n"));
    EXPECT_TRUE(text.contains("CYCL DEF 26.1 X 1.5 CCX+20\n"));
    EXPECT_TRUE(text.contains("  QS500=\"KERF\""));
}

// Counts the highlight-coloured pixels of the rendered picture inside `area`.
int highlightedPixels(const QImage& image, const QRectF& area) {
    int count = 0;
    const QRect box = area.toAlignedRect().intersected(image.rect());
    for (int y = box.top(); y <= box.bottom(); ++y) {
        for (int x = box.left(); x <= box.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() > 200 && c.green() > 80 && c.green() < 150 && c.blue() < 60) ++count;
        }
    }
    return count;
}

TEST(CycleHelpPicture, HighlightsADifferentDimensionPerParameter) {
    test::testApp();
    CycleDialog dialog(*cycles::findCycle(200), false);
    CycleHelpPicture* picture = dialog.picture();
    dialog.resize(1000, 700);
    dialog.setCurrentField(0);  // Q200
    const QImage clearanceImage = picture->grab().toImage();
    const QRectF clearance = picture->highlightRect();
    dialog.setCurrentField(1);  // Q201
    const QImage depthImage = picture->grab().toImage();
    const QRectF depth = picture->highlightRect();
    ASSERT_FALSE(clearance.isEmpty());
    ASSERT_FALSE(depth.isEmpty());
    EXPECT_FALSE(clearance.intersects(depth));
    // Set-up clearance is above the surface, depth below it (the picture is a side section).
    EXPECT_LT(clearance.bottom(), depth.bottom());
    EXPECT_GT(highlightedPixels(clearanceImage, clearance), 10);
    EXPECT_EQ(highlightedPixels(clearanceImage, depth), 0);
    EXPECT_GT(highlightedPixels(depthImage, depth), 10);
    EXPECT_EQ(highlightedPixels(depthImage, clearance), 0);
}

TEST(CycleHelpPicture, EveryCycleHasAPictureWithHighlightedParameters) {
    test::testApp();
    for (const cycles::CycleDescriptor* cycle : cycles::allCycles()) {
        CycleDialog dialog(*cycle, false);
        dialog.picture()->resize(300, 300);
        int highlighted = 0;
        for (int i = 0; i < dialog.fieldCount(); ++i) {
            dialog.setCurrentField(i);
            if (!dialog.picture()->highlightRect().isEmpty()) ++highlighted;
        }
        EXPECT_GT(highlighted, 0) << "cycle " << cycle->number;
    }
}

// Stands in for a .qm file: the Portuguese names of the seed (seed 000 §2.1).
class PortugueseCycles : public QTranslator {
public:
    QString translate(const char* context, const char* source, const char* disambiguation,
                      int n) const override {
        (void)disambiguation;
        (void)n;
        const QString text = QString::fromUtf8(source);
        if (QString::fromUtf8(context) != "kerf") return {};
        if (text == "DRILLING") return QStringLiteral("FURAR");
        if (text == "SET-UP CLEARANCE") return QStringLiteral("DISTANCIA SEGURANCA");
        if (text.startsWith("Set-up clearance")) return QStringLiteral("Distância de segurança");
        return {};
    }
    bool isEmpty() const override { return false; }
};

TEST(CycleDialog, LanguageSwitchChangesNamesDescriptionsAndComments) {
    test::testApp();
    CycleDialog dialog(*cycles::findCycle(200), false);
    const QString englishBlock = dialog.blocks().first();
    PortugueseCycles portuguese;
    QCoreApplication::installTranslator(&portuguese);
    QCoreApplication::processEvents();
    const QString block = dialog.blocks().first();
    const QString title = dialog.findChild<QLabel*>("cycleTitle")->text();
    const QString help = dialog.findChild<QLabel*>("cycleFieldHelp")->text();
    QCoreApplication::removeTranslator(&portuguese);
    QCoreApplication::processEvents();

    EXPECT_TRUE(
        englishBlock.startsWith("CYCL DEF 200 DRILLING ~\n  Q200=+2      ;SET-UP CLEARANCE"));
    EXPECT_TRUE(block.startsWith("CYCL DEF 200 FURAR ~\n  Q200=+2      ;DISTANCIA SEGURANCA ~"))
        << block.toStdString();
    EXPECT_EQ(title, "CYCL DEF 200 FURAR");
    EXPECT_EQ(help, QStringLiteral("Q200: Distância de segurança"));
    EXPECT_EQ(dialog.findChild<QLabel*>("cycleTitle")->text(), "CYCL DEF 200 DRILLING");
}

}  // namespace
}  // namespace kerf::ui
