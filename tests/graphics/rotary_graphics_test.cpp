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

Drawn run(const std::string& program, const std::string& machine = "mill5") {
    app::RunOptions options;
    options.program = kPrograms / program;
    options.toolTable = kPrograms / "TOOL.T";
    options.machine = machine;
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
    EXPECT_EQ(drawn.stock->mesh(60).shadeAboutAxis, -1);  // a box: shaded by height
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

// The seed's cycle 27 example (chapter 8) on mill4, whose A table lies along X through the
// workpiece origin (rotary/c27_mill4.H: the seed's program without PLANE, L A+0 for L C+0). The
// development's v (the contour's Y) runs along the A axis, the part's X; u = 25 a turns the
// table by a, and the tool, along machine +Z, meets the part at (v, -r sin a, r cos a): the
// table turns the part by Rot(X, -a). Without BLK FORM the cycle defines the blank along X:
// radius Q16 = 25 over v 20 - 7.5 (the corner arcs' reach) - 7 (two tool radii) - 10 = -4.5 to
// 60 + 7.5 + 7 + 10 = 84.5, pi 25^2 89 = 174751 mm^3. The D7 tool's centre runs round u
// 33.5..46.5 by v 23.5..56.5 down to r 18, so the contour's band u 30..37 is cut, the island
// u 37..43 inside it and everything outside u 30..50 stays.
struct OnTheCylinder {
    double u;
    double v;
    double r;
    Vec3 point() const {
        const double a = u / 25.0;
        return {v, -r * std::sin(a), r * std::cos(a)};
    }
};

void expectCylinderAlongXWithTheSeedsGroove(const Drawn& drawn, size_t rapidCuts) {
    ASSERT_TRUE(drawn.stock);
    const graphics::VoxelStock* voxels = drawn.stock->voxelStock();
    ASSERT_NE(voxels, nullptr) << "a cylinder lying along X needs the 3D stock";
    EXPECT_EQ(drawn.stock->millStock(), nullptr);
    const double blank = kPi * 25.0 * 25.0 * 89.0;
    EXPECT_NEAR(drawn.stock->initialVolumeMm3(), blank, 0.01 * blank);
    EXPECT_NEAR(voxels->minCorner().x(), -4.5, voxels->cellMm());
    EXPECT_NEAR(voxels->maxCorner().x(), 84.5, voxels->cellMm());
    // The groove (tool centre at u 33.5, the side v 23.5..56.5; the end u 30..50 at v 23.5).
    for (const OnTheCylinder air :
         {OnTheCylinder{33.5, 40.0, 19.0}, OnTheCylinder{31.0, 40.0, 24.5},
          OnTheCylinder{46.5, 30.0, 19.0}, OnTheCylinder{40.0, 23.5, 19.0}})
        EXPECT_FALSE(voxels->solidAt(air.point())) << "u " << air.u << " v " << air.v;
    // Below the floor, the island, outside the contour, beyond its ends along the axis, and the
    // other side of the cylinder: material.
    for (const OnTheCylinder solid :
         {OnTheCylinder{33.5, 40.0, 17.0}, OnTheCylinder{40.0, 40.0, 24.5},
          OnTheCylinder{28.0, 40.0, 24.5}, OnTheCylinder{40.0, 17.0, 24.5},
          OnTheCylinder{40.0, 63.0, 24.5}, OnTheCylinder{33.5 + 25.0 * kPi, 40.0, 24.5}})
        EXPECT_TRUE(voxels->solidAt(solid.point())) << "u " << solid.u << " v " << solid.v;
    // Material outside the blank's radius is not made up: nothing beyond r 25 or past its ends.
    EXPECT_FALSE(voxels->solidAt({40.0, 0.0, 25.5}));
    EXPECT_FALSE(voxels->solidAt({85.5, 0.0, 0.0}));
    EXPECT_TRUE(voxels->solidAt({84.0, 0.0, 0.0}));
    // The groove's area on the development is its centre line times the tool's width, 85.1327 x 7
    // (corners of radius 4 > 3.5 do not overlap); across the circumference its depth 25 - 18
    // counts as (25^2 - 18^2) / (2 x 25) = 6.02 mm of shell, along the axis the flat tool leaves
    // the chord segment 7 x 7 less the surface's sag, 48.43 mm^2 over the width 7: 6.92 mm.
    // A rapid cut from the start on the axis up through the blank adds the column pi 3.5^2 25.
    const double area = 85.1327 * 7.0;
    const double bore = static_cast<double>(rapidCuts) * kPi * 3.5 * 3.5 * 25.0;
    EXPECT_GT(drawn.stock->removedVolumeMm3(), 0.98 * (area * 6.02 + bore));
    EXPECT_LT(drawn.stock->removedVolumeMm3(), 1.02 * (area * 6.92 + bore));
    EXPECT_EQ(drawn.stock->rapidCuts(), rapidCuts);
    // Drawn shaded by the distance from the A axis, as a turned part.
    EXPECT_EQ(drawn.stock->mesh(60).shadeAboutAxis, 0);
}

TEST(RotaryGraphics, CylinderSurfaceCycleOnTheATableCutsACylinderAlongX) {
    expectCylinderAlongXWithTheSeedsGroove(run("c27_mill4.H", "mill4"), 0);
}

// The same blank written by hand: BLK FORM CYLINDER X R25 L89 DIST+84.5. It is there from the
// start, which the interpreter takes at the workpiece origin, on the A axis inside the blank:
// block 2's L Z+250 leaves it by one rapid cut (docs/klartext.md), along the axis at v 0, away
// from the groove.
TEST(RotaryGraphics, BlkFormCylinderAlongXIsTheATablesBlank) {
    expectCylinderAlongXWithTheSeedsGroove(run("c27_blk_mill4.H", "mill4"), 1);
}

}  // namespace
}  // namespace kerf
