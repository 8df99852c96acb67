// FAGOR canned cycles written from the panel: each cycle's dialog has the interpreter's
// parameters, writes the exact block, refuses what the interpreter refuses, edits a cycle block
// in place, and the written program passes the FAGOR check.
#include "ui/cycles/fagor_cycle_dialog.h"

#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QTest>
#include <QTextBlock>
#include <QTimer>
#include <map>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "ui/cycles/cycle_help_picture.h"
#include "ui/cycles/fagor_program_entry.h"
#include "ui/cycles/fagor_softkeys.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_text_check.h"

namespace kerf::ui {
namespace {

// Types `values` (letter -> text) into the dialog the way an operator does: each field in turn,
// type, Enter; fields not in `values` are left empty.
void typeValues(FagorCycleDialog& dialog, const std::map<char, QString>& values) {
    for (int i = 0; i < dialog.fieldCount(); ++i) {
        ASSERT_EQ(dialog.currentField(), i) << dialog.message().toStdString();
        QLineEdit* input = dialog.input(i);
        input->selectAll();
        const char letter = dialog.input(i)->objectName().back().toLatin1();
        if (const auto it = values.find(letter); it != values.end())
            QTest::keyClicks(input, it->second);
        else
            input->clear();
        QTest::keyClick(input, Qt::Key_Return);
    }
}

QString letters(const FagorCycleDialog& dialog) {
    QString text;
    for (int i = 0; i < dialog.fieldCount(); ++i)
        text += dialog.input(i)->objectName().back();
    return text;
}

// The parameters of each cycle in the order of the manual (spec part 2 §2).
TEST(FagorCycleDialog, HasOneFieldPerParameterOfTheCycle) {
    test::testApp();
    const std::map<int, QString> expected = {
        {66, "XZICALMHSEQ"},      {68, "XZCDLMKFHSEQ"}, {69, "XZCDLMKFHSEQ"},
        {81, "XZQRCDLMFH"},       {82, "XZQRCDLMFH"},   {83, "XZIBDKHCLR"},
        {84, "XZQRCDLMFHIK"},     {85, "XZQRCDLMFHIK"}, {86, "XZQRKIBEDLCJAWVM"},
        {87, "XZQRKIBEDLCJAWVM"}, {88, "XZQRCDK"},      {89, "XZQRCDK"},
    };
    for (const auto& [g, fields] : expected) {
        FagorCycleDialog dialog(g);
        EXPECT_EQ(letters(dialog), fields) << g;
        EXPECT_TRUE(dialog.findChild<QLabel*>("cycleTitle")
                        ->text()
                        .startsWith(QStringLiteral("G%1  ").arg(g)));
    }
}

// The manual gives allowances, pass steps and thread depths in radius though X is a diameter:
// the unit says so where it does (spec part 2 §2), and only there.
TEST(FagorCycleDialog, LengthsTheManualGivesInRadiusSaySo) {
    test::testApp();
    auto unitOf = [](int g, char letter) {
        for (const FagorField& field : fagorCycleFields(g)) {
            if (field.parameter->letter == letter) return fagorUnitText(field.unit);
        }
        return QStringLiteral("none");
    };
    const QString radius = QStringLiteral("mm (radius)");
    for (const char letter : {'C', 'L'})
        EXPECT_EQ(unitOf(68, letter), radius) << letter;
    for (const char letter : {'I', 'C', 'L'})
        EXPECT_EQ(unitOf(66, letter), radius) << letter;
    for (const char letter : {'I', 'B', 'D', 'L'})
        EXPECT_EQ(unitOf(86, letter), radius) << letter;
    EXPECT_EQ(unitOf(88, 'D'), radius);
    EXPECT_EQ(unitOf(89, 'C'), radius);
    // X, Z, the Z allowance M, G88's step along Z, G69's step along Z, G87's depth along Z, the
    // pitch: plain lengths.
    EXPECT_EQ(unitOf(68, 'X'), QStringLiteral("mm"));
    EXPECT_EQ(unitOf(68, 'M'), QStringLiteral("mm"));
    EXPECT_EQ(unitOf(88, 'C'), QStringLiteral("mm"));
    EXPECT_EQ(unitOf(69, 'C'), QStringLiteral("mm"));
    EXPECT_EQ(unitOf(87, 'I'), QStringLiteral("mm"));
    EXPECT_EQ(unitOf(86, 'C'), QStringLiteral("mm"));
}

struct Filled {
    int g;
    std::map<char, QString> values;
    QString block;
};

// Each family's block, written by hand in the manual's parameter order.
TEST(FagorCycleDialog, WritesTheCycleBlockOfTheTypedValues) {
    test::testApp();
    const std::vector<Filled> cases = {
        {68,
         {{'X', "0"},
          {'Z', "0"},
          {'C', "2"},
          {'D', "1"},
          {'L', "0.4"},
          {'M', "0.2"},
          {'K', "0.1"},
          {'F', "0.25"},
          {'H', "0.12"},
          {'S', "10"},
          {'E', "20"}},
         "G68 X0 Z0 C2 D1 L0.4 M0.2 K0.1 F0.25 H0.12 S10 E20"},
        {66,
         {{'X', "80"},
          {'Z', "5"},
          {'I', "6"},
          {'C', "2"},
          {'A', "1"},
          {'S', "100"},
          {'E', "200"},
          {'Q', "12"}},
         "G66 X80 Z5 I6 C2 A1 S100 E200 Q12"},
        {81,
         {{'X', "60"}, {'Z', "2"}, {'Q', "40"}, {'R', "-30"}, {'C', "1.5"}, {'H', "0.1"}},
         "G81 X60 Z2 Q40 R-30 C1.5 H0.1"},
        {85,
         {{'X', "20"}, {'Z', "0"}, {'Q', "40"}, {'R', "-10"}, {'C', "1"}, {'I', "10"}, {'K', "0"}},
         "G85 X20 Z0 Q40 R-10 C1 I10 K0"},
        {83,
         {{'X', "0"}, {'Z', "2"}, {'I', "30"}, {'B', "5"}, {'D', "2"}, {'K', "50"}},
         "G83 X0 Z2 I30 B5 D2 K50"},
        {86,
         {{'X', "30"},
          {'Z', "2"},
          {'Q', "30"},
          {'R', "-40"},
          {'I', "1.2"},
          {'B', "0.3"},
          {'C', "2"},
          {'A', "30"},
          {'V', "2"}},
         "G86 X30 Z2 Q30 R-40 I1.2 B0.3 C2 A30 V2"},
        {89,
         {{'X', "40"}, {'Z', "-20"}, {'Q', "30"}, {'R', "-25"}, {'C', "2.5"}, {'K', "100"}},
         "G89 X40 Z-20 Q30 R-25 C2.5 K100"},
    };
    for (const Filled& c : cases) {
        FagorCycleDialog dialog(c.g);
        typeValues(dialog, c.values);
        EXPECT_EQ(dialog.result(), QDialog::Accepted) << c.g << dialog.message().toStdString();
        EXPECT_EQ(dialog.block(), c.block);
    }
}

TEST(FagorCycleDialog, RefusesAMissingRequiredParameterWithTheInterpretersMessage) {
    test::testApp();
    FagorCycleDialog dialog(68);
    QTest::keyClicks(dialog.input(0), "0");
    QTest::keyClick(dialog.input(0), Qt::Key_Return);
    QTest::keyClicks(dialog.input(1), "0");
    QTest::keyClick(dialog.input(1), Qt::Key_Return);
    ASSERT_EQ(dialog.currentField(), dialog.fieldOf('C'));
    QTest::keyClick(dialog.input(dialog.fieldOf('C')), Qt::Key_Return);  // C left empty
    EXPECT_EQ(dialog.message(), "G68 needs its parameter C");
    EXPECT_EQ(dialog.currentField(), dialog.fieldOf('C'));
    // OK with C given but S and E empty: refused on S, nothing accepted.
    dialog.input(dialog.fieldOf('C'))->setText("2");
    dialog.accept();
    EXPECT_EQ(dialog.message(), "G68 needs its parameter S");
    EXPECT_EQ(dialog.currentField(), dialog.fieldOf('S'));
    EXPECT_NE(dialog.result(), QDialog::Accepted);
}

// The interpreter's format rules: C of G68 is 5.5 unsigned and not 0, A of G66 is 0 or 1, the
// labels S/E have four digits, one field holds one value.
TEST(FagorCycleDialog, RefusesValuesOutsideTheManualsFormat) {
    test::testApp();
    const struct {
        int g;
        char letter;
        const char* typed;
    } refused[] = {
        {68, 'C', "0"},   {68, 'C', "-2"},    {68, 'C', "123456"}, {68, 'C', "1.123456"},
        {66, 'A', "2"},   {68, 'S', "10000"}, {68, 'S', "1.5"},    {68, 'C', "2 F1"},
        {68, 'C', "2F1"}, {83, 'I', "0"},     {68, 'E', "20;"},    {68, 'E', "20 N3"},
        {86, 'B', "0"},   {88, 'K', "-1"},
    };
    for (const auto& r : refused) {
        FagorCycleDialog dialog(r.g);
        const int field = dialog.fieldOf(r.letter);
        ASSERT_GE(field, 0);
        dialog.setCurrentField(field);
        QTest::keyClicks(dialog.input(field), r.typed);
        QTest::keyClick(dialog.input(field), Qt::Key_Return);
        EXPECT_FALSE(dialog.message().isEmpty()) << r.g << r.letter << r.typed;
        EXPECT_EQ(dialog.currentField(), field) << r.g << r.letter << r.typed;
    }
    FagorCycleDialog zero(68);
    zero.setCurrentField(zero.fieldOf('C'));
    QTest::keyClicks(zero.input(zero.fieldOf('C')), "0");
    QTest::keyClick(zero.input(zero.fieldOf('C')), Qt::Key_Return);
    EXPECT_EQ(zero.message(), "C of G68 cannot be 0");
}

// A rule between two parameters: the thread repass K excludes the pitch change M (G86).
TEST(FagorCycleDialog, RefusesRepassWithPitchChangeOnTheMField) {
    test::testApp();
    FagorCycleDialog dialog(86);
    typeValues(dialog, {{'X', "30"},
                        {'Z', "2"},
                        {'Q', "30"},
                        {'R', "-40"},
                        {'K', "-20"},
                        {'I', "1.2"},
                        {'B', "0.3"},
                        {'C', "2"},
                        {'M', "0.1"}});
    EXPECT_NE(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(dialog.currentField(), dialog.fieldOf('M'));
    EXPECT_EQ(dialog.message(), "G86: M (pitch change) cannot be programmed with K (repass)");
}

TEST(FagorCycleDialog, HelpPictureHighlightsTheFieldBeingEntered) {
    test::testApp();
    for (const int g : {66, 68, 81, 83, 84, 86, 88}) {
        FagorCycleDialog dialog(g);
        dialog.resize(1000, 600);
        dialog.setCurrentField(dialog.fieldOf('X'));
        const QRectF x = dialog.picture()->highlightRect();
        EXPECT_FALSE(x.isEmpty()) << g;
        dialog.setCurrentField(dialog.fieldOf(g == 83 ? 'I' : 'C'));
        EXPECT_FALSE(dialog.picture()->highlightRect().isEmpty()) << g;
        EXPECT_NE(dialog.picture()->highlightRect(), x) << g;
    }
    // Feeds have no dimension: nothing is highlighted.
    FagorCycleDialog stock(68);
    stock.setCurrentField(stock.fieldOf('F'));
    EXPECT_TRUE(stock.picture()->highlightRect().isEmpty());
}

const QString kProgram = QStringLiteral(
    "N1 G90 G95 F0.2 S800 M3\n"
    "N2 G00 X70 Z5\n"
    "N4 M30\n"
    "N30 G01 X40 Z-10\n"
    "G01 Z-4\n"
    "N40 G01 X20 Z0");

template <typename Fill>
void answerNextDialog(Fill fill) {
    QTimer::singleShot(0, [fill] {
        auto* dialog = qobject_cast<FagorCycleDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        fill(*dialog);
    });
}

// The softkey G69 of "Canned cycles" writes the cycle after the cursor's block with the next free
// label, and the program passes the FAGOR check (spec example of golden cycle_g69_facing_stock).
TEST(FagorProgrammingSoftkeys, CannedCycleKeyWritesTheBlockAndTheProgramChecksClean) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(program::Dialect::Fagor);
    editor.setPlainText(kProgram);
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(1)));
    std::vector<SoftkeyRow> shown;
    bool back = false;
    const SoftkeyPaging paging{[&shown](std::vector<SoftkeyRow> rows) { shown = std::move(rows); },
                               [&back] { back = true; }};
    const std::vector<SoftkeyRow> rows = programmingEntryRows(&editor, nullptr, paging);
    ASSERT_EQ(rows.size(), 1u);
    ASSERT_EQ(rows[0][0].id, "fagorCycles");
    rows[0][0].action();
    ASSERT_EQ(shown.size(), 2u);  // 12 cycles, seven a row, with Back
    QStringList ids;
    for (const SoftkeyRow& row : shown) {
        for (const Softkey& key : row)
            ids << key.id;
    }
    EXPECT_EQ(ids.join(' '),
              "fagorCycle66 fagorCycle68 fagorCycle69 fagorCycle81 fagorCycle82 fagorCycle83 "
              "fagorCycle84 back fagorCycle85 fagorCycle86 fagorCycle87 fagorCycle88 fagorCycle89 "
              "back");
    EXPECT_TRUE(shown[0][2].text.startsWith("G69\n"));

    answerNextDialog([](FagorCycleDialog& dialog) {
        typeValues(dialog, {{'X', "60"},
                            {'Z', "-10"},
                            {'C', "5"},
                            {'D', "1"},
                            {'H', "0.1"},
                            {'S', "30"},
                            {'E', "40"}});
    });
    shown[0][2].action();
    EXPECT_TRUE(back);
    const QString written = QStringLiteral(
        "N1 G90 G95 F0.2 S800 M3\n"
        "N2 G00 X70 Z5\n"
        "N3 G69 X60 Z-10 C5 D1 H0.1 S30 E40\n"
        "N4 M30\n"
        "N30 G01 X40 Z-10\n"
        "G01 Z-4\n"
        "N40 G01 X20 Z0");
    EXPECT_EQ(editor.toPlainText(), written);
    EXPECT_EQ(editor.textCursor().blockNumber(), 2);
    const auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    const DiagnosticList diagnostics =
        checkProgramText(written.toStdString(), "PART.pim", program::Dialect::Fagor, *lathe, {});
    for (const Diagnostic& d : diagnostics)
        ADD_FAILURE() << d.messageTemplate;
    // Cancelled: nothing written, still one undo step for the cycle.
    answerNextDialog([](FagorCycleDialog& dialog) { dialog.reject(); });
    shown[0][0].action();
    EXPECT_EQ(editor.toPlainText(), written);
    editor.undo();
    EXPECT_EQ(editor.toPlainText(), kProgram);
}

// The editor numbers a new line of a numbered program ("N60 "): a cycle written there goes into
// that line after its label, not onto a new unnumbered line below an empty block.
TEST(FagorProgrammingSoftkeys, ACycleGoesIntoALineThatHoldsOnlyItsLabel) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(program::Dialect::Fagor);
    editor.setPlainText("N50 G00 X44 Z-30\nN60 \nN70 M30");
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(1)));
    answerNextDialog([](FagorCycleDialog& dialog) {
        typeValues(dialog, {{'X', "40"}, {'Z', "-38"}, {'Q', "34"}, {'R', "-44"}, {'C', "2"}});
    });
    ASSERT_TRUE(defineFagorCycle(editor, nullptr, 88));
    EXPECT_EQ(editor.toPlainText(), "N50 G00 X44 Z-30\nN60 G88 X40 Z-38 Q34 R-44 C2\nN70 M30");
    EXPECT_EQ(editor.textCursor().blockNumber(), 1);
    // A line with a block after its label keeps it: the cycle goes below.
    editor.setPlainText("N50 G00 X44 Z-30\nN70 M30");
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(0)));
    answerNextDialog([](FagorCycleDialog& dialog) {
        typeValues(dialog, {{'X', "40"}, {'Z', "-38"}, {'Q', "34"}, {'R', "-44"}, {'C', "2"}});
    });
    ASSERT_TRUE(defineFagorCycle(editor, nullptr, 88));
    EXPECT_EQ(editor.toPlainText(), "N50 G00 X44 Z-30\nN60 G88 X40 Z-38 Q34 R-44 C2\nN70 M30");
}

// "Edit cycle" on a cycle block: the dialog shows its values; the words are replaced, the label
// and the comment stay.
TEST(FagorProgrammingSoftkeys, EditCycleRewritesTheCycleUnderTheCursor) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(program::Dialect::Fagor);
    editor.setPlainText(
        "N2 G00 X70 Z5\n"
        "N3 G69 X60 Z-10 C5 D1 H0.1 S30 E40 ; rough the face\n"
        "N4 M30");
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(1)));
    QStringList seen;
    answerNextDialog([&seen](FagorCycleDialog& dialog) {
        seen = dialog.values();
        dialog.input(dialog.fieldOf('C'))->setText("2.5");
        dialog.input(dialog.fieldOf('D'))->clear();
        dialog.accept();
    });
    ASSERT_TRUE(editFagorCycleAtCursor(editor, nullptr));
    EXPECT_EQ(seen.join(','), "60,-10,5,1,,,,,0.1,30,40,");
    EXPECT_EQ(editor.toPlainText(),
              "N2 G00 X70 Z5\n"
              "N3 G69 X60 Z-10 C2.5 H0.1 S30 E40 ; rough the face\n"
              "N4 M30");
    // Not a cycle block: nothing opens.
    editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(0)));
    EXPECT_FALSE(editFagorCycleAtCursor(editor, nullptr));
}

// "Edit cycle" away from a cycle block explains why in a box titled with the FAGOR's name of
// the mode (Editing, spec part 2 §5.15 OPMODE), not the TNC's "Programming".
TEST(FagorProgrammingSoftkeys, EditCycleHintSpeaksOfTheEditingMode) {
    test::testApp();
    ProgramEditor editor;
    editor.setDialect(program::Dialect::Fagor);
    editor.setPlainText("N2 G00 X70 Z5\nN4 M30");
    const SoftkeyPaging paging{[](std::vector<SoftkeyRow>) {}, [] {}};
    const std::vector<SoftkeyRow> rows = programmingEntryRows(&editor, nullptr, paging);
    ASSERT_EQ(rows[0][1].id, "editCycle");
    QString title;
    QString text;
    QTimer::singleShot(0, [&title, &text] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        ASSERT_NE(box, nullptr);
        title = box->windowTitle();
        text = box->text();
        box->accept();
    });
    rows[0][1].action();
    EXPECT_EQ(title, QStringLiteral("Editing"));
    EXPECT_TRUE(text.contains("G66-G89")) << text.toStdString();
}

}  // namespace
}  // namespace kerf::ui
