// `kerf --mode testrun --screenshot`: the picture is taken only once the finished stock is in
// the scene and the view is fitted to the part. Needs a real (virtual) X display: the 3D view does
// not exist on the offscreen platform.
#include <QApplication>
#include <QTest>
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>
#include <vtkRenderer.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "graphics/scene/scene_vtk.h"
#include "graphics/stock/progressive_stock.h"
#include "motion/sim/simulated_clock.h"
#include "test_paths.h"
#include "tests/ui/viewport/viewport_test_app.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/test_run_screen.h"
#include "ui/testrun/test_run_controller.h"
#include "ui/viewport/graphics_panel.h"
#include "ui/viewport/viewport_widget.h"

namespace kerf::ui {
namespace {

// A blank far from the machine's origin (X+200..260, Y+150..190): a view not yet fitted (the
// viewport's first, around the origin) shows none of it.
const char* kFarPart =
    "0 BEGIN PGM FAR MM\n"
    "1 BLK FORM 0.1 Z X+200 Y+150 Z-20\n"
    "2 BLK FORM 0.2 X+260 Y+190 Z+0\n"
    "3 TOOL CALL 1 Z S2000\n"
    "4 L Z+5 R0 FMAX\n"
    "5 L X+210 Y+160 R0 FMAX\n"
    "6 L Z-5 R0 F500\n"
    "7 L X+250 F1000\n"
    "8 L Z+5 R0 FMAX\n"
    "9 END PGM FAR MM\n";

// The content's eight corners in the renderer's pixels.
std::vector<std::array<double, 2>> cornersOnScreen(graphics::Scene& scene) {
    vtkRenderer* renderer = graphics::vtkRendererOf(scene);
    const graphics::Bounds3 box = scene.contentBounds();
    std::vector<std::array<double, 2>> corners;
    for (int k = 0; k < 8; ++k) {
        renderer->SetWorldPoint((k & 1) != 0 ? box.max.x() : box.min.x(),
                                (k & 2) != 0 ? box.max.y() : box.min.y(),
                                (k & 4) != 0 ? box.max.z() : box.min.z(), 1.0);
        renderer->WorldToDisplay();
        const double* p = renderer->GetDisplayPoint();
        corners.push_back({p[0], p[1]});
    }
    return corners;
}

TEST(TestRunPicture, WaitsForTheFinishedStockInAViewFittedToThePart) {
    test::viewportTestApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_testrun_picture");
    std::filesystem::copy_file(
        std::filesystem::path(KERF_SOURCE_DIR) / "tests/graphics/programs/TOOL.T", dir / "TOOL.T");
    ASSERT_FALSE(writeFileAtomically(dir / "FAR.H", kFarPart).has_value());
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.machiningClock = motion::makeSimulatedClock;
    MainWindow window(std::move(context));
    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    ASSERT_TRUE(window.openProgram(dir / "FAR.H"));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));

    // As `kerf --screenshot` does: the picture is taken the moment this returns. Several times,
    // the window resized in between (each resize asks for a new fit), since the stock and the fit
    // arrive on timers: a picture taken too early shows up in some of the rounds.
    for (int round = 0; round < 6; ++round) {
        SCOPED_TRACE(round);
        if (round > 0) window.resize(round % 2 == 0 ? 1280 : 1200, round % 2 == 0 ? 800 : 760);
        ASSERT_TRUE(finishTestRunForPicture(window, 60000));
        GraphicsPanel* graphics = window.graphics();
        ASSERT_NE(graphics->viewport(), nullptr);
        EXPECT_EQ(window.testRun()->state(), TestRunController::State::Finished);
        EXPECT_FALSE(graphics->fitPending());
        // The finished stock is in the picture, not the blank (12 triangles) shown before it.
        const auto stock = window.testRun()->stock()->latest();
        ASSERT_TRUE(stock->finished);
        ASSERT_TRUE(stock->mesh);
        EXPECT_GT(stock->mesh->triangleCount(), 12u);
        EXPECT_EQ(graphics->scene().stats().stockTriangles, stock->mesh->triangleCount());
        // Fitted: every corner of the part's box inside the picture, and the box spanning most of
        // its width or height (a fit leaves an 8 % margin).
        const int* size = graphics::vtkRendererOf(graphics->scene())->GetSize();
        const double width = size[0];
        const double height = size[1];
        double minX = width, maxX = 0.0, minY = height, maxY = 0.0;
        for (const auto& [x, y] : cornersOnScreen(graphics->scene())) {
            EXPECT_GE(x, 0.0);
            EXPECT_LE(x, width);
            EXPECT_GE(y, 0.0);
            EXPECT_LE(y, height);
            minX = std::min(minX, x);
            maxX = std::max(maxX, x);
            minY = std::min(minY, y);
            maxY = std::max(maxY, y);
        }
        EXPECT_GT(std::max((maxX - minX) / width, (maxY - minY) / height), 0.8);
    }
}

}  // namespace
}  // namespace kerf::ui
