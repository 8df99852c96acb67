#include "ui/viewport/graphics_panel.h"

#include <QApplication>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "motion/sim/simulated_clock.h"
#include "test_paths.h"
#include "tests/ui/viewport/viewport_test_app.h"
#include "ui/viewport/viewport_widget.h"

namespace kerf::ui {
namespace {

// Two drilled holes, then a slot; line n of the file is block n - 1. Line 9 is the only move
// between X+15 and X+30 (a rapid at Z+5 along Y+20).
const char* kParts =
    "0 BEGIN PGM PARTS MM\n"
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
    "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
    "3 TOOL CALL 1 Z S2000\n"
    "4 L Z+5 R0 FMAX\n"
    "5 L X+15 Y+20 R0 FMAX\n"
    "6 L Z-10 R0 F100\n"
    "7 L Z+5 R0 FMAX\n"
    "8 L X+30 Y+20 R0 FMAX\n"
    "9 L Z-10 R0 F100\n"
    "10 L Z+5 R0 FMAX\n"
    "11 TOOL CALL 2 Z S3000\n"
    "12 L X+60 Y+40 R0 FMAX\n"
    "13 L Z-2 R0 F200\n"
    "14 L X+90 F300\n"
    "15 L Z+5 R0 FMAX\n"
    "16 END PGM PARTS MM\n";

TEST(GraphicsPanel, FormatsDurationsAsHoursMinutesSeconds) {
    EXPECT_EQ(GraphicsPanel::formatDuration(0.0), QStringLiteral("0:00:00"));
    EXPECT_EQ(GraphicsPanel::formatDuration(59.2), QStringLiteral("0:01:00"));
    EXPECT_EQ(GraphicsPanel::formatDuration(3725.0), QStringLiteral("1:02:05"));
}

TEST(GraphicsPanel, ShowsTheTestRunPicksBlocksAndLightsUpTheCursorBlock) {
    test::viewportTestApp();
    const auto root = kerf::test::uniqueTempDir("graphics_panel");
    std::filesystem::copy_file(
        std::filesystem::path(KERF_SOURCE_DIR) / "tests/graphics/programs/TOOL.T", root / "TOOL.T");
    const machine::MachineConfig machine = *machine::loadMachine("mill");
    TestRunController controller(machine, root);
    controller.setMachiningClock(motion::makeSimulatedClock);
    controller.setTickMs(0);
    GraphicsPanel panel(controller, machine);
    panel.resize(800, 600);
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    ASSERT_NE(panel.viewport(), nullptr);

    QSignalSpy ready(&controller, &TestRunController::programReady);
    controller.prepare(QString::fromUtf8(kParts), root / "PARTS.H", program::Dialect::Klartext);
    ASSERT_TRUE(ready.wait(20000));
    // The blank appears before anything is cut.
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.scene().stats().stockTriangles > 0; }, 20000));

    // Machining time: the program run's (simulated), more than the feeds' 26.1 s (15 mm at F100
    // twice, 7 mm at F200, 30 mm at F300).
    const double totalS = controller.machiningTimeS();
    EXPECT_GT(totalS, 9.0 + 9.0 + 2.1 + 6.0);
    EXPECT_TRUE(panel.timeLabel()->text().endsWith(GraphicsPanel::formatDuration(totalS)))
        << panel.timeLabel()->text().toStdString();

    // Top view, parallel projection: the content's box fills the height (margin 1.08) or width.
    panel.viewport()->setView(graphics::View::Top);
    QApplication::processEvents();
    QWidget* area = panel.viewport()->renderArea();
    const graphics::Bounds3 box = panel.scene().contentBounds();
    const double w = area->width();
    const double h = area->height();
    const double halfHeightMm =
        std::max((box.max.y() - box.min.y()) / 2.0, (box.max.x() - box.min.x()) / 2.0 / (w / h)) *
        1.08;
    const double pixelsPerMm = h / 2.0 / halfHeightMm;
    auto pixelOf = [&](double x, double y) {
        return QPoint(
            static_cast<int>(std::lround(w / 2.0 + (x - box.centre().x()) * pixelsPerMm)),
            static_cast<int>(std::lround(h / 2.0 - (y - box.centre().y()) * pixelsPerMm)));
    };
    QSignalSpy picked(&panel, &GraphicsPanel::blockPicked);
    QTest::mouseClick(area, Qt::LeftButton, Qt::NoModifier, pixelOf(22.5, 20.0));
    ASSERT_EQ(picked.count(), 1);
    EXPECT_EQ(picked.at(0).at(0).toInt(), 9);
    QTest::mouseClick(area, Qt::LeftButton, Qt::NoModifier, pixelOf(75.0, 40.0));  // the slot
    ASSERT_EQ(picked.count(), 2);
    EXPECT_EQ(picked.at(1).at(0).toInt(), 15);

    // The editor's cursor on line 7 (one drilling move) lights up its one segment.
    panel.highlightLine(7);
    EXPECT_EQ(panel.scene().stats().highlightedSegments, 1u);
    panel.highlightLine(0);
    EXPECT_EQ(panel.scene().stats().highlightedSegments, 0u);

    // The speed buttons set the playback speed.
    panel.speedButton(TestRunSpeed::Times100)->click();
    EXPECT_EQ(controller.speed(), TestRunSpeed::Times100);
    controller.setSpeed(TestRunSpeed::Real);
    EXPECT_TRUE(panel.speedButton(TestRunSpeed::Real)->isChecked());
}

}  // namespace
}  // namespace kerf::ui
