// Rotary tables in the graphics: a program on mill5 drills two holes into a side face of the blank
// with PLANE SPATIAL SPB+90; the stock and the toolpath must show them on that face, not on top.
//
// By hand (rotary/side_holes.H). The blank is X-20..+20, Y-20..+20, Z-30..0; the workpiece origin
// is the pivot (mill5's preset). SPB+90 turns the plane about Y by +90: tilted X = part -Z, tilted
// Y = part Y, tilted Z (the tool) = part +X, so a tilted point (x', y', z') is the part's
// (z', y', -x'). Hole 1 at X+10 Y+5 from Z+25 to Z+12: on the part the axis runs along X from 25 to
// 12 at y 5, z -10: 8 mm deep behind the face x = 20. Hole 2 at X+20 Y-8: y -8, z -20, the same
// depth. Tool D5 flat: each hole pi 2.5^2 8 = 157.08 mm^3.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "app/runner/session.h"
#include "core/canon/tee_sink.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/toolpath/toolpath_data.h"

namespace kerf {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
const fs::path kPrograms = fs::path(KERF_SOURCE_DIR) / "tests" / "graphics" / "rotary";

struct Drawn {
    std::unique_ptr<graphics::StockSimulation> stock;
    graphics::ToolpathData path;
};

Drawn run(const std::string& program) {
    app::RunOptions options;
    options.program = kPrograms / program;
    options.toolTable = kPrograms / "TOOL.T";
    options.machine = "mill5";
    auto session = app::openSession(options);
    Drawn out;
    EXPECT_TRUE(session && session->ready());
    if (!session || !session->ready()) return out;
    const auto frame = machine::WorkpieceFrame::of(session->machine, session->workOffset);
    EXPECT_TRUE(frame.has_value());
    graphics::StockOptions stockOptions;
    stockOptions.workpieceFrame = frame;
    out.stock = std::make_unique<graphics::StockSimulation>(stockOptions);
    graphics::ToolpathOptions pathOptions;
    pathOptions.workpieceFrame = frame;
    graphics::ToolpathCollector path(pathOptions);
    canon::TeeSink tee;
    tee.add(*out.stock);
    tee.add(path);
    interp::Interpreter& interpreter = *session->program.interpreter;
    out.stock->setStart(interpreter.nominalPosition());
    path.setStart(interpreter.nominalPosition());
    for (;;) {
        const interp::RunStatus status = interpreter.run(tee, 100000);
        if (status != interp::RunStatus::BudgetUsed) {
            EXPECT_EQ(status, interp::RunStatus::Finished);
            break;
        }
    }
    for (const Diagnostic& d : interpreter.diagnostics())
        EXPECT_NE(d.severity, Severity::Error) << d.code << " " << d.message();
    out.stock->finish();
    out.path = path.take();
    return out;
}

TEST(RotaryGraphics, HolesDrilledInATiltedPlaneAreOnTheSideFace) {
    const Drawn drawn = run("side_holes.H");
    ASSERT_TRUE(drawn.stock);
    const graphics::VoxelStock* voxels = drawn.stock->voxelStock();
    ASSERT_NE(voxels, nullptr) << "a tilted tool needs the 3D stock";
    EXPECT_EQ(drawn.stock->millStock(), nullptr);
    // Inside the holes, half way down: air.
    EXPECT_FALSE(voxels->solidAt({16.0, 5.0, -10.0}));
    EXPECT_FALSE(voxels->solidAt({19.5, 5.0, -10.0}));
    EXPECT_FALSE(voxels->solidAt({16.0, -8.0, -20.0}));
    // Beside a hole, beyond its bottom, and the whole top face: material.
    EXPECT_TRUE(voxels->solidAt({16.0, 5.0, -6.5}));
    EXPECT_TRUE(voxels->solidAt({16.0, 8.5, -10.0}));
    EXPECT_TRUE(voxels->solidAt({11.0, 5.0, -10.0}));
    EXPECT_TRUE(voxels->solidAt({11.0, -8.0, -20.0}));
    for (double x : {-10.0, 0.0, 10.0, 12.0, 16.0, 19.5})
        for (double y : {-8.0, 5.0})
            EXPECT_TRUE(voxels->solidAt({x, y, -0.2})) << "top face at X" << x << " Y" << y;
    const double expected = 2.0 * kPi * 2.5 * 2.5 * 8.0;
    EXPECT_NEAR(drawn.stock->removedVolumeMm3(), expected, 0.01 * expected);
    EXPECT_EQ(drawn.stock->rapidCuts(), 0u);
}

TEST(RotaryGraphics, ToolpathIsDrawnOnTheTurnedPartWithTheToolsDirection) {
    const Drawn drawn = run("side_holes.H");
    const graphics::ToolpathData& path = drawn.path;
    ASSERT_EQ(path.toolAxis.size(), path.xyz.size());
    // The first feed move (block 8) ends at the bottom of hole 1, the tool along part +X.
    bool found = false;
    for (size_t m = 0; m < path.moveCount() && !found; ++m) {
        if (path.kinds[m] != graphics::MoveKind::Feed) continue;
        const auto [begin, end] = path.pointsOfMove(m);
        ASSERT_LT(begin, end);
        const Vec3 tip = path.point(end - 1);
        EXPECT_NEAR(tip.x(), 12.0, 1e-4);
        EXPECT_NEAR(tip.y(), 5.0, 1e-4);
        EXPECT_NEAR(tip.z(), -10.0, 1e-4);
        const Vec3 axis = path.toolAxisAt(end - 1);
        EXPECT_NEAR(axis.x(), 1.0, 1e-6);
        EXPECT_NEAR(axis.z(), 0.0, 1e-6);
        found = true;
    }
    EXPECT_TRUE(found);
    // The table's turn (TURN: B from 0 to 90) is drawn as an arc about the pivot, in steps of at
    // most 1 deg: more than 90 points.
    EXPECT_GT(path.pointCount(), 90u);
}

// A simultaneous move (rotary/tcpm_line.H): with TCPM the tip goes along the line y 0, z -5 from
// X-30 to X+30 while B turns from 0 to 60. On the part every drawn point of it lies on that line
// (within half the path tolerance of 0.01 mm, the interpreter's split) and the tool ends along
// (sin 60, 0, cos 60). The flat D5 tool cuts a groove 5 deep: air on the line, material 2.5 mm
// beside it (the tool turns about Y, so the groove stays R wide in Y) and below the lowest edge of
// its tilted end, which inside the blank stays above z -5 - 2.5 sin 52 = -6.97.
TEST(RotaryGraphics, SimultaneousMoveIsDrawnAndCutOnThePart) {
    const Drawn drawn = run("tcpm_line.H");
    ASSERT_TRUE(drawn.stock);
    const graphics::ToolpathData& path = drawn.path;
    size_t feedPoints = 0;
    Vec3 lastAxis = Vec3::UnitZ();
    for (size_t m = 0; m < path.moveCount(); ++m) {
        if (path.kinds[m] != graphics::MoveKind::Feed) continue;
        const auto [begin, end] = path.pointsOfMove(m);
        for (size_t i = begin; i < end; ++i) {
            const Vec3 p = path.point(i);
            EXPECT_NEAR(p.y(), 0.0, 0.005) << "point " << i;
            EXPECT_NEAR(p.z(), -5.0, 0.005) << "point " << i;
            ++feedPoints;
            lastAxis = path.toolAxisAt(i);
        }
    }
    EXPECT_GT(feedPoints, 60u);  // B turns 60 deg: at least a point a degree
    EXPECT_NEAR(lastAxis.x(), std::sqrt(3.0) / 2.0, 1e-6);
    EXPECT_NEAR(lastAxis.z(), 0.5, 1e-6);
    const graphics::VoxelStock* voxels = drawn.stock->voxelStock();
    ASSERT_NE(voxels, nullptr);
    for (double x : {-15.0, 0.0, 15.0}) {
        EXPECT_FALSE(voxels->solidAt({x, 0.0, -4.0})) << "X" << x;
        EXPECT_TRUE(voxels->solidAt({x, 3.0, -4.0})) << "X" << x;
        EXPECT_TRUE(voxels->solidAt({x, 0.0, -7.2})) << "X" << x;
    }
}

}  // namespace
}  // namespace kerf
