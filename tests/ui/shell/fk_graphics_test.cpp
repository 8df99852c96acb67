#include <QPushButton>
#include <QTest>
#include <QTextBlock>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/cycles/fk_solution_keys.h"
#include "ui/editor/fk_sketch_view.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"

// The FK programming graphics in Programming: an arc typed with only its radius and end point
// has two solutions; the softkeys show them and write the one chosen as FSELECT.
namespace kerf::ui {
namespace {

bool hasFkError(const DiagnosticList& diagnostics, uint32_t line) {
    for (const Diagnostic& d : diagnostics)
        if (d.code == "fk" && d.severity == Severity::Error && d.line == line) return true;
    return false;
}

QString lineText(const ProgramEditor& editor, int line) {
    return editor.document()->findBlockByNumber(line - 1).text();
}

TEST(FkGraphics, AnAmbiguousArcOffersItsTwoSolutionsAndSelectWritesFselect) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_fk_graphics");
    ASSERT_FALSE(writeFileAtomically(dir / "FK.H",
                                     "0 BEGIN PGM FK MM\n1 L X+0 Y+0 R0 FMAX\n2 L Z-2 F200\n"
                                     "3 FL X+30 Y+10\n4 END PGM FK MM\n")
                     .has_value());
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    MainWindow window(context);
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.openProgram(dir / "FK.H"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    ProgramPanel& panel = *window.program();
    ProgramEditor& editor = *panel.editor();

    // The operator enters an arc from (0,0) to (10,10) known by its radius only, after block 2.
    editor.goToLine(3);
    editor.moveCursor(QTextCursor::EndOfBlock);
    editor.insertBlock();
    QTest::keyClicks(&editor, "FC DR+ R10 X+10 Y+10");
    ASSERT_EQ(lineText(editor, 4), QStringLiteral("3 FC DR+ R10 X+10 Y+10"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.fkOffer().has_value(); }, 10000));

    // Two circles of radius 10 pass through both points: centres (0,10) and (10,0).
    const std::optional<ProgramPanel::FkOffer> offer = panel.fkOffer();
    EXPECT_EQ(offer->solutions, 2);
    EXPECT_EQ(offer->shown, 1);
    EXPECT_EQ(offer->chosen, 0);
    EXPECT_EQ(offer->afterLine, 4u);
    EXPECT_TRUE(panel.fkSketch()->isVisible());
    // The live check says the element needs FSELECT, at its block.
    EXPECT_TRUE(hasFkError(panel.diagnostics(), 4));
    // The softkeys to choose come first.
    EXPECT_EQ(window.softkeys()->currentRow(), 0);
    EXPECT_EQ(window.softkeys()->keyButton(0)->text(), QStringLiteral("Show\nsolution"));
    EXPECT_EQ(window.softkeys()->keyButton(1)->text(), QStringLiteral("Select\nsolution"));

    const task::ProgramSketch* sketch = panel.fkSketch()->sketch();
    ASSERT_NE(sketch, nullptr);
    ASSERT_EQ(sketch->fk.ambiguities.size(), 1u);
    const std::vector<PlanarSegment> alternatives = sketch->fk.ambiguities[0].alternatives;
    ASSERT_EQ(alternatives.size(), 2u);
    const Vec2 centres[2] = {alternatives[0].center, alternatives[1].center};
    EXPECT_NEAR(std::min((centres[0] - Vec2(0, 10)).norm(), (centres[1] - Vec2(0, 10)).norm()), 0.0,
                1e-9);
    EXPECT_NEAR(std::min((centres[0] - Vec2(10, 0)).norm(), (centres[1] - Vec2(10, 0)).norm()), 0.0,
                1e-9);

    // An edit makes the offer's lines stale: nothing is written until the check comes back.
    QTest::keyClick(&editor, Qt::Key_Space);
    EXPECT_TRUE(panel.fkOfferStale());
    const QString edited = editor.toPlainText();
    EXPECT_FALSE(writeFkSelect(panel, 1));
    EXPECT_EQ(editor.toPlainText(), edited);
    QTest::keyClick(&editor, Qt::Key_Backspace);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !panel.fkOfferStale(); }, 10000));

    // Show solution cycles 1 -> 2 -> 1 -> 2; Select solution writes the one shown.
    ASSERT_TRUE(window.softkeys()->pressId("fkShowSolution"));
    EXPECT_EQ(panel.fkOffer()->shown, 2);
    ASSERT_TRUE(window.softkeys()->pressId("fkShowSolution"));
    EXPECT_EQ(panel.fkOffer()->shown, 1);
    ASSERT_TRUE(window.softkeys()->pressId("fkShowSolution"));
    const QString before = editor.toPlainText();
    ASSERT_TRUE(window.softkeys()->pressId("fkSelectSolution"));
    EXPECT_EQ(lineText(editor, 5), QStringLiteral("4 FSELECT 2"));
    EXPECT_EQ(lineText(editor, 6), QStringLiteral("5 FL X+30 Y+10"));
    EXPECT_EQ(lineText(editor, 7), QStringLiteral("6 END PGM FK MM"));

    // The check of the new text: no FK error; the arc is the solution chosen.
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return panel.fkOffer().has_value() && panel.fkOffer()->chosen == 2; }, 10000));
    EXPECT_FALSE(hasFkError(panel.diagnostics(), 4));
    sketch = panel.fkSketch()->sketch();
    ASSERT_GE(sketch->fk.elements.size(), 2u);
    ASSERT_TRUE(sketch->fk.elements[0].segment.has_value());
    EXPECT_NEAR((sketch->fk.elements[0].segment->center - alternatives[1].center).norm(), 0.0,
                1e-9);
    EXPECT_EQ(panel.fkOffer()->selectLine, 5u);

    // Choosing again rewrites the FSELECT in place.
    ASSERT_TRUE(window.softkeys()->pressId("fkShowSolution"));
    ASSERT_TRUE(window.softkeys()->pressId("fkSelectSolution"));
    EXPECT_EQ(lineText(editor, 5), QStringLiteral("4 FSELECT 1"));
    EXPECT_EQ(lineText(editor, 6), QStringLiteral("5 FL X+30 Y+10"));

    // Both are edits the operator can undo.
    editor.undo();
    EXPECT_EQ(lineText(editor, 5), QStringLiteral("4 FSELECT 2"));
    editor.undo();
    EXPECT_EQ(editor.toPlainText(), before);
}

}  // namespace
}  // namespace kerf::ui
