#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

#include "canon_builder.h"
#include "core/geometry/arc_math.h"
#include "core/tables/tool_table.h"
#include "graphics/stock/cutter.h"
#include "graphics/stock/height_field_stock.h"
#include "graphics/stock/lathe_stock.h"
#include "graphics/stock/machine_stock_options.h"
#include "graphics/stock/progressive_stock.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/stock/tool_mesh.h"

namespace kerf::graphics {
namespace {

using test::CanonBuilder;

// Analytic volume of a drilled hole: cylinder down to where the cone starts, plus the cone.
double drilledHole(double radius, double depth, double pointAngleDeg) {
    const double cone = radius / std::tan(degToRad(pointAngleDeg) / 2.0);
    return kPi * radius * radius * (depth - cone) + kPi * radius * radius * cone / 3.0;
}

TEST(Cutter, ShapesFromToolTableColumns) {
    EXPECT_EQ(MillCutter::fromGeometry(5, 0).kind, CutterKind::Flat);
    EXPECT_EQ(MillCutter::fromGeometry(3, 3).kind, CutterKind::Ball);
    EXPECT_EQ(MillCutter::fromGeometry(5, 2).kind, CutterKind::BullNose);
    EXPECT_EQ(MillCutter::fromGeometry(2.5, 0, 118).kind, CutterKind::Drill);
    EXPECT_EQ(MillCutter::fromGeometry(2.5, 0, 180).kind, CutterKind::Flat);
    EXPECT_EQ(MillCutter::fromGeometry(-1, 0).radiusMm, 0.0);
    EXPECT_FALSE(MillCutter::fromGeometry(std::nan(""), 0).cuts());

    const MillCutter ball = MillCutter::fromGeometry(3, 3);
    EXPECT_DOUBLE_EQ(ball.heightAt(0), 0.0);
    EXPECT_NEAR(ball.heightAt(3), 3.0, 1e-12);
    EXPECT_TRUE(std::isinf(ball.heightAt(3.01)));
    const MillCutter bull = MillCutter::fromGeometry(5, 2);
    EXPECT_DOUBLE_EQ(bull.heightAt(3), 0.0);
    EXPECT_NEAR(bull.heightAt(5), 2.0, 1e-12);
    const MillCutter drill = MillCutter::fromGeometry(2.5, 0, 90);
    EXPECT_NEAR(drill.heightAt(2.5), 2.5, 1e-12);

    // Volumes below a height: hemisphere, cone + cylinder.
    EXPECT_NEAR(ball.volumeBelow(3), 2.0 / 3.0 * kPi * 27, 1e-9);
    EXPECT_NEAR(drill.volumeBelow(10), drilledHole(2.5, 10, 90), 1e-9);
    EXPECT_NEAR(MillCutter::fromGeometry(5, 0).volumeBelow(2), kPi * 25 * 2, 1e-9);
    // Bull nose: disc of radius 3 plus torus section; check against numeric integration.
    double numeric = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double z = (i + 0.5) * 4.0 / n;
        // radius of the solid at height z
        double r = 5.0;
        if (z < 2.0) r = 3.0 + std::sqrt(4.0 - (2.0 - z) * (2.0 - z));
        numeric += kPi * r * r * 4.0 / n;
    }
    EXPECT_NEAR(bull.volumeBelow(4), numeric, 1e-3);
}

TEST(Cutter, LatheInsertTipCodes) {
    LatheInsert insert;
    insert.noseRadiusMm = 0.8;
    insert.locationCode = 3;  // tip lower-left of the nose centre: centre at +X +Z of the tip
    auto [dx, dz] = insert.noseCentreOffset();
    EXPECT_DOUBLE_EQ(dx, 0.8);
    EXPECT_DOUBLE_EQ(dz, 0.8);
    insert.locationCode = 9;
    EXPECT_EQ(insert.noseCentreOffset(), std::make_pair(-0.0, -0.0));
    insert.locationCode = 6;
    EXPECT_EQ(insert.noseCentreOffset().second, -0.8);
    insert.locationCode = 3;
    insert.includedAngleDeg = 80;
    insert.edgeLengthMm = 10;
    const auto outline = insert.outline(16);
    // Every outline point lies on the far side of the tip (+X, +Z quadrant from the tip, with
    // a little slack for the nose arc).
    for (const auto& [x, z] : outline) {
        EXPECT_GE(x, -1e-9);
        EXPECT_GE(z, -1e-9);
    }
    EXPECT_GT(latheInsertMesh(insert).triangleCount(), 10u);
    EXPECT_GT(millToolMesh(MillCutter::fromGeometry(3, 3)).triangleCount(), 100u);
}

TEST(HeightField, ThreeDrilledHolesRemoveTheirAnalyticVolume) {
    // Drill D5, 118 degrees, three holes 10 mm deep from Z0 with plain moves.
    StockOptions options;
    options.millCutter = [](const canon::ToolChange& t) {
        return MillCutter::fromGeometry(t.geometry.radiusMm, 0.0, 118.0);
    };
    StockSimulation simulation(options);
    CanonBuilder b;
    b.box(Vec3(0, 0, -20), Vec3(60, 40, 0)).tool(1, 2.5).rapid(0, 0, 5);
    for (double x : {15.0, 30.0, 45.0})
        b.rapid(x, 20, 5).line(x, 20, -10).rapid(x, 20, 5);
    b.feed(simulation);
    simulation.finish();
    const double expected = 3 * drilledHole(2.5, 10, 118);
    EXPECT_NEAR(simulation.removedVolumeMm3(), expected, 0.02 * expected);
    EXPECT_EQ(simulation.rapidCuts(), 0u);  // retracting through the hole removes nothing
    EXPECT_DOUBLE_EQ(simulation.initialVolumeMm3(), 60 * 40 * 20);
    EXPECT_EQ(simulation.stockSource(), "program");
}

TEST(HeightField, ATouchProbeRemovesNothingAndAMillWithTheSameMovesDoes) {
    // Tool 1 has a TP_NO in TOOL.T (a touch probe, ball R2), tool 2 none: the same moves 1 mm
    // into the blank's top, a plunge and 20 mm along X. The probe's stylus touches; only the
    // flat D4 mill cuts: a stadium of 2 r L + pi r^2 by 1 mm.
    auto tools = tables::ToolTable::parse(
        "BEGIN TOOL.T MM\n"
        "T    NAME     L        R        TP_NO\n"
        "1    PROBE    +50      +2       1\n"
        "2    MILL     +60      +2\n"
        "[END]\n",
        "TOOL.T");
    ASSERT_TRUE(tools.ok()) << tools.error().format();
    StockOptions options;
    options.millCutter = millCutterFromToolTable(&*tools);
    for (int tool : {1, 2}) {
        StockSimulation simulation(options);
        CanonBuilder b;
        b.box(Vec3(0, 0, -20), Vec3(60, 40, 0)).tool(tool, 2.0).rapid(20, 20, 5);
        b.line(20, 20, -1).line(40, 20, -1).rapid(40, 20, 5);
        b.feed(simulation);
        simulation.finish();
        const double expected = tool == 1 ? 0.0 : (2 * 2 * 20 + kPi * 4) * 1;
        EXPECT_NEAR(simulation.removedVolumeMm3(), expected, 0.02 * expected + 1e-9) << tool;
    }
    // The stylus is drawn, as a ball.
    const MillCutter stylus = options.millCutter(canon::ToolChange{1, "PROBE", {50, 2}});
    EXPECT_TRUE(stylus.touchProbe);
    EXPECT_FALSE(stylus.cuts());
    EXPECT_EQ(stylus.kind, CutterKind::Ball);
    EXPECT_GT(millToolMesh(stylus).triangleCount(), 100u);
}

TEST(HeightField, FlatPocketAndBallSlotMatchAnalyticVolumes) {
    const double cell = 0.1;
    {
        // Flat D10 slot 30 mm long, 3 mm deep: a stadium of area 2 r L + pi r^2.
        HeightFieldStock stock(Vec3(-10, -10, -10), Vec3(50, 10, 0), cell, 100'000'000);
        const MillCutter flat = MillCutter::fromGeometry(5, 0);
        stock.cut(Vec3(0, 0, 5), Vec3(0, 0, -3), flat);
        stock.cut(Vec3(0, 0, -3), Vec3(30, 0, -3), flat);
        const double expected = (2 * 5 * 30 + kPi * 25) * 3;
        EXPECT_NEAR(stock.removedVolumeMm3(), expected, 0.01 * expected);
    }
    {
        // Circular pocket from the canonical stream: plunge at the centre, one full circle of
        // radius 4 with a D10 flat mill: a disc of radius 9, 3 mm deep.
        StockSimulation simulation;
        CanonBuilder b;
        b.box(Vec3(-20, -20, -10), Vec3(20, 20, 0)).tool(1, 5.0).rapid(0, 0, 5).line(0, 0, -3);
        b.line(4, 0, -3).arc(4, 0, -3, 0, 0, 2 * kPi).line(0, 0, -3).rapid(0, 0, 5);
        b.feed(simulation);
        simulation.finish();
        const double expected = kPi * 81 * 3;
        EXPECT_NEAR(simulation.removedVolumeMm3(), expected, 0.01 * expected);
    }
    {
        // Ball D6 slot 40 mm long 2 mm deep: half cylinder section times length plus a sphere
        // cap at each end... with depth < r: segment area times length + one spherical cap.
        HeightFieldStock stock(Vec3(-10, -10, -10), Vec3(60, 10, 0), cell, 100'000'000);
        const MillCutter ball = MillCutter::fromGeometry(3, 3);
        const double depth = 2.0;
        stock.cut(Vec3(0, 0, 5), Vec3(0, 0, -depth), ball);
        stock.cut(Vec3(0, 0, -depth), Vec3(40, 0, -depth), ball);
        // Circle segment of height h in a circle of radius r: r^2 acos((r-h)/r) - (r-h)
        // sqrt(2rh-h^2)
        const double r = 3;
        const double h = depth;
        const double segment =
            r * r * std::acos((r - h) / r) - (r - h) * std::sqrt(2 * r * h - h * h);
        const double cap = kPi * h * h * (3 * r - h) / 3.0;  // two half caps
        const double expected = segment * 40 + cap;
        EXPECT_NEAR(stock.removedVolumeMm3(), expected, 0.02 * expected);
    }
    {
        // A ramp with a bull-nose tool removes at least the straight plunge and never more than
        // the bounding prism.
        HeightFieldStock stock(Vec3(-10, -10, -10), Vec3(40, 10, 0), cell, 100'000'000);
        const MillCutter bull = MillCutter::fromGeometry(5, 2);
        stock.cut(Vec3(0, 0, 0), Vec3(30, 0, -3), bull);
        const double removed = stock.removedVolumeMm3();
        EXPECT_GT(removed, 0.0);
        EXPECT_LT(removed, 40 * 10 * 3);
        // The deepest point is at the end of the ramp: 3 mm.
        double lowest = 0.0;
        for (int j = 0; j < stock.cellsY(); ++j) {
            for (int i = 0; i < stock.cellsX(); ++i)
                lowest = std::min(lowest, stock.topAt(i, j));
        }
        EXPECT_NEAR(lowest, -3.0, 0.01);
    }
}

TEST(HeightField, BallRampMatchesGoldenSectionReference) {
    // The closed-form ball sweep agrees with a brute-force sampling of the tool along the move.
    const MillCutter ball = MillCutter::fromGeometry(3, 3);
    HeightFieldStock exact(Vec3(-5, -5, -6), Vec3(25, 5, 0), 0.25, 10'000'000);
    exact.cut(Vec3(0, 0, 1), Vec3(20, 1, -4), ball);
    HeightFieldStock sampled(Vec3(-5, -5, -6), Vec3(25, 5, 0), 0.25, 10'000'000);
    const int steps = 4000;
    for (int k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) / steps;
        const Vec3 p = Vec3(0, 0, 1) + t * Vec3(20, 1, -5);
        sampled.cut(p, p, ball);
    }
    for (int j = 0; j < exact.cellsY(); ++j) {
        for (int i = 0; i < exact.cellsX(); ++i) {
            // Sampling can only leave material (higher or equal), by a few microns here.
            EXPECT_LE(exact.topAt(i, j), sampled.topAt(i, j) + 1e-5);
            EXPECT_NEAR(exact.topAt(i, j), sampled.topAt(i, j), 0.01);
        }
    }
}

TEST(HeightField, MeshIsClosedAndItsVolumeMatches) {
    HeightFieldStock stock(Vec3(0, 0, -10), Vec3(20, 10, 0), 0.1, 10'000'000);
    const Mesh before = stock.mesh(1000);
    EXPECT_NEAR(std::fabs(before.signedVolume()), 2000.0, 1e-3);
    EXPECT_NEAR(before.bounds.max.z(), 0.0, 1e-6);
    stock.cut(Vec3(5, 5, 5), Vec3(5, 5, -4), MillCutter::fromGeometry(2, 0));
    const Mesh after = stock.mesh(64);  // coarse display grid
    EXPECT_GT(after.triangleCount(), 0u);
    EXPECT_LE(after.vertexCount(), 64u * 64u + 4u * 4u * 64u + 4u);
}

TEST(HeightField, DegenerateInputs) {
    HeightFieldStock tiny(Vec3(0, 0, 0), Vec3(0, 0, 0), 0.1, 100);
    EXPECT_EQ(tiny.removedVolumeMm3(), 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    HeightFieldStock stock(Vec3(0, 0, -1), Vec3(1e9, 1e9, 0), 0.1, 1'000'000);  // coarsened
    EXPECT_LE(static_cast<size_t>(stock.cellsX()) * static_cast<size_t>(stock.cellsY()),
              1'000'000u);
    EXPECT_FALSE(stock.cut(Vec3(nan, 0, 0), Vec3(1, 1, -1), MillCutter::fromGeometry(1, 0)));
    EXPECT_FALSE(stock.cut(Vec3(0, 0, 0), Vec3(1, 1, -1), MillCutter{}));  // radius 0
    EXPECT_FALSE(stock.cut(Vec3(-1e300, 0, -1), Vec3(1e300, 0, -1), MillCutter{}));
    stock.cut(Vec3(-1e300, 0, -0.5), Vec3(1e300, 0, -0.5), MillCutter::fromGeometry(1, 0));
    EXPECT_GE(stock.removedVolumeMm3(), 0.0);
    (void)stock.mesh(32);
}

TEST(LatheStock, TurningADiameterRemovesTheRing) {
    // Bar D50 from Z-60 to Z0, turned to D40 over 30 mm in passes along Z with a centre-code
    // insert of R0.4 (bands 0.8 wide, 0.6 apart, the last one with its centre at X = 20.4), each
    // pass backing out along itself: the ring r 20..25, z -30..0, plus the nose's rounded ends
    // below Z-30 (at most 0.4 mm x 5 mm of profile at r <= 25).
    LatheBar bar;
    bar.radiusMm = 25;
    bar.zMin = -60;
    bar.zMax = 0;
    LatheStock stock(bar, 0.05, 50'000'000);
    EXPECT_NEAR(stock.initialVolumeMm3(), kPi * 25 * 25 * 60, 1e-6 * kPi * 25 * 25 * 60);
    LatheInsert insert;
    insert.noseRadiusMm = 0.4;
    insert.locationCode = 9;
    for (double x = 24.6; x >= 20.4 - 1e-9; x -= 0.6) {
        stock.cut(x, 2, x, -30, insert);
        stock.cut(x, -30, x, 2, insert);
    }
    const double ring = kPi * (25 * 25 - 20 * 20) * 30;
    EXPECT_GE(stock.removedVolumeMm3(), 0.995 * ring);
    EXPECT_LE(stock.removedVolumeMm3(), ring + 2 * kPi * 25 * 0.4 * 5);
    const Mesh half = stock.mesh(180.0, 32, 400);
    EXPECT_GT(half.triangleCount(), 0u);
    EXPECT_LE(half.bounds.max.y(), 1e-6);  // the half section keeps Y <= 0
    EXPECT_NEAR(half.bounds.min.x(), -25.0, 0.2);
}

TEST(LatheStock, FacingPastTheAxisAndDegenerateInputs) {
    LatheBar bar;
    bar.radiusMm = 10;
    bar.zMin = -20;
    bar.zMax = 0;
    LatheStock stock(bar, 0.05, 10'000'000);
    LatheInsert insert;
    insert.noseRadiusMm = 0.2;
    insert.locationCode = 9;
    // Face 1 mm off in three passes (bands 0.4 wide) with the nose going 1 mm past the axis.
    for (double z : {-0.2, -0.5, -0.8})
        stock.cut(12, z, -1, z, insert);
    const double disc = kPi * 100 * 1.0;
    EXPECT_NEAR(stock.removedVolumeMm3(), disc, 0.03 * disc);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(stock.cut(nan, 0, 1, 1, insert));
    LatheBar broken;
    broken.radiusMm = nan;
    LatheStock empty(broken, 0.1, 1000);
    EXPECT_EQ(empty.removedVolumeMm3(), 0.0);
    (void)empty.mesh();
}

TEST(LatheStock, TheHolderSideOfTheInsertIsSolid) {
    // One external pass (code 3, tip towards the axis and the chuck) at X18 along Z0..Z-20 in a
    // bar of radius 25: the holder clears everything outside the nose, the ring r 18..25 (the
    // rounded nose end leaves at most 0.4 mm x 7 mm of profile at Z-20).
    LatheBar bar;
    bar.radiusMm = 25;
    bar.zMin = -40;
    bar.zMax = 0;
    LatheStock external(bar, 0.05, 50'000'000);
    LatheInsert insert;
    insert.noseRadiusMm = 0.4;
    insert.locationCode = 3;
    external.cut(18, 2, 18, -20, insert);
    const double ring = kPi * (25 * 25 - 18 * 18) * 20;
    EXPECT_NEAR(external.removedVolumeMm3(), ring, 0.01 * ring);
    EXPECT_TRUE(external.material(static_cast<int>(17.9 / 0.05), static_cast<int>(30.0 / 0.05)));
    EXPECT_FALSE(external.material(static_cast<int>(24.9 / 0.05), static_cast<int>(30.0 / 0.05)));

    // A boring tool (code 8, tip pointing away from the axis) at X10 in a bar bored to radius 5:
    // the bar behind it clears the ring r 5..10, and below Z-20 at most the nose's 0.4 mm.
    bar.innerRadiusMm = 5;
    LatheStock bored(bar, 0.05, 50'000'000);
    insert.locationCode = 8;
    bored.cut(10, 2, 10, -20, insert);
    const double inner = kPi * (10 * 10 - 5 * 5) * 20;
    EXPECT_GE(bored.removedVolumeMm3(), 0.995 * inner);
    EXPECT_LE(bored.removedVolumeMm3(), inner + kPi * (10 * 10 - 5 * 5) * 0.4);
    EXPECT_TRUE(bored.material(static_cast<int>(10.2 / 0.05), static_cast<int>(30.0 / 0.05)));
}

TEST(LatheStock, RevolvedOutlineClosedTowardsTheAxis) {
    // A cone from r10 at Z0 to r20 at Z-31, closed to the axis: pi h (R^2 + R r + r^2) / 3.
    // (A slope whose radii fall between the cell centres: on a 1:3 slope every third row's edge
    // runs through a cell centre, and those ties fall outside.)
    const LatheStock cone =
        LatheStock::revolved({{10.0, 0.0}, {20.0, -31.0}}, {-1.0, 0.0}, nullptr, 0.1, 10'000'000);
    const double frustum = kPi * 31.0 * (100.0 + 200.0 + 400.0) / 3.0;
    EXPECT_NEAR(cone.initialVolumeMm3(), frustum, 0.001 * frustum);
    EXPECT_NEAR(cone.bar().radiusMm, 20.0, 1e-9);
    EXPECT_NEAR(cone.bar().zMin, -31.0, 1e-9);
    EXPECT_NEAR(cone.bar().zMax, 0.0, 1e-9);
}

TEST(LatheStock, RevolvedOutlineClosedAwayFromTheAxisAndAlongZ) {
    // A bore outline r10 from Z0 to Z-20 inside a r25 bar: closed outwards to the bar's r25.
    LatheBar bar;
    bar.radiusMm = 25.0;
    bar.zMin = -60.0;
    bar.zMax = 0.0;
    const LatheStock tube =
        LatheStock::revolved({{10.0, 0.0}, {10.0, -20.0}}, {1.0, 0.0}, &bar, 0.1, 10'000'000);
    EXPECT_NEAR(tube.initialVolumeMm3(), kPi * (625.0 - 100.0) * 20.0, 1e-6 * 33000.0);
    // A face outline at Z2 from r0 to r30, the material towards -Z: closed at the bar's end Z-60.
    const LatheStock slug =
        LatheStock::revolved({{0.0, 2.0}, {30.0, 2.0}}, {0.0, -1.0}, &bar, 0.1, 10'000'000);
    EXPECT_NEAR(slug.initialVolumeMm3(), kPi * 900.0 * 62.0, 1e-6 * 175000.0);
}

TEST(StockSimulation, ARawProfileReplacesTheBarOnlyBeforeTheFirstCut) {
    StockOptions options;
    options.machine = StockMachine::Lathe;
    LatheBar bar;
    bar.radiusMm = 30;
    bar.zMin = -100;
    bar.zMax = 0;
    options.bar = bar;
    canon::StockRevolved casting;  // r15 from Z2 to Z-40, to the axis
    casting.outline = {Vec3(15, 0, 2), Vec3(15, 0, -40)};
    casting.materialSide = Vec3(-1, 0, 0);
    {
        StockSimulation simulation(options);
        simulation.consume(canon::Command{{}, canon::StockDefinition{casting}});
        simulation.finish();
        EXPECT_EQ(simulation.stockSource(), "program");
        EXPECT_NEAR(simulation.initialVolumeMm3(), kPi * 225.0 * 42.0, 1e-6 * 30000.0);
    }
    StockSimulation simulation(options);
    simulation.setStart(CanonBuilder::pose(40, 0, 5));
    CanonBuilder b;
    b.tool(1, 0.4).rapid(28, 0, 5).line(28, 0, -10);
    b.feed(simulation);
    simulation.consume(canon::Command{{}, canon::StockDefinition{casting}});
    simulation.finish();
    EXPECT_EQ(simulation.stockSource(), "bar");
    EXPECT_NEAR(simulation.initialVolumeMm3(), kPi * 900.0 * 100.0, 1.0);
    ASSERT_EQ(simulation.notes().size(), 1u);
}

TEST(StockSimulation, LatheInsertTakesTheTipCodeOfTheToolChange) {
    // The same boring pass through the canonical stream: the offset's tip code 8 makes it a
    // boring tool (the default insert is external, code 3, and would clear r >= 10 instead).
    StockOptions options;
    options.machine = StockMachine::Lathe;
    LatheBar bar;
    bar.radiusMm = 25;
    bar.innerRadiusMm = 5;
    bar.zMin = -40;
    bar.zMax = 0;
    options.bar = bar;
    StockSimulation simulation(options);
    simulation.setStart(CanonBuilder::pose(0, 0, 5));
    canon::ToolChange boringBar;
    boringBar.number = 2;
    boringBar.geometry.radiusMm = 0.4;
    boringBar.geometry.locationCode = 8;
    CanonBuilder b;
    b.add(boringBar).rapid(10, 0, 2).line(10, 0, -20).line(10, 0, 2).rapid(0, 0, 5);
    b.feed(simulation);
    simulation.finish();
    const double inner = kPi * (10 * 10 - 5 * 5) * 20;
    EXPECT_GE(simulation.removedVolumeMm3(), 0.995 * inner);
    EXPECT_LE(simulation.removedVolumeMm3(), inner + kPi * (10 * 10 - 5 * 5) * 0.4);
}

TEST(StockSimulation, LatheFromCanonicalStreamInXZPlane) {
    StockOptions options;
    options.machine = StockMachine::Lathe;
    LatheBar bar;
    bar.radiusMm = 20;
    bar.zMin = -50;
    bar.zMax = 0;
    options.bar = bar;
    options.latheInsert = [](const canon::ToolChange& tool) {
        LatheInsert insert;
        insert.noseRadiusMm = tool.geometry.radiusMm;
        insert.locationCode = 9;
        return insert;
    };
    StockSimulation simulation(options);
    // Nose R2.5 centred at X17.5 (radius) down to Z-20 and back: the ring r 15..20 over 20 mm,
    // and below Z-20, t deep, the holder side clears from the nose, r = 17.5 - s with
    // s = sqrt(6.25 - t^2), out to r = 20: the integral over t of pi (400 - (17.5 - s)^2), with
    // int s dt = pi 6.25 / 4 (a quarter disc) and int s^2 dt = 6.25 * 2.5 - 2.5^3 / 3.
    simulation.setStart(CanonBuilder::pose(25, 0, 2));  // not the origin, inside the bar's face
    CanonBuilder b;
    b.tool(1, 2.5).rapid(25, 0, 2).rapid(17.5, 0, 2).line(17.5, 0, -20).line(17.5, 0, 2);
    b.feed(simulation);
    simulation.finish();
    const double below = kPi * (2.5 * (400 - 17.5 * 17.5) + 2 * 17.5 * kPi * 6.25 / 4 -
                                (6.25 * 2.5 - 2.5 * 2.5 * 2.5 / 3));
    const double expected = kPi * (20 * 20 - 15 * 15) * 20 + below;
    EXPECT_NEAR(simulation.removedVolumeMm3(), expected, 0.01 * expected);
    EXPECT_EQ(simulation.stockSource(), "bar");
}

TEST(StockSimulation, DerivesABlankWhenTheProgramHasNone) {
    StockOptions options;
    options.deriveStockFromPath = true;
    StockSimulation simulation(options);
    CanonBuilder b;
    b.tool(1, 2.0).rapid(0, 0, 5).line(0, 0, -2).line(20, 0, -2);
    b.feed(simulation);
    simulation.finish();
    EXPECT_EQ(simulation.stockSource(), "derived");
    ASSERT_TRUE(simulation.hasStock());
    EXPECT_GT(simulation.removedVolumeMm3(), 0.0);
    ASSERT_FALSE(simulation.notes().empty());
}

TEST(StockSimulation, NoBlankAndNoDerivationLeavesANote) {
    StockSimulation simulation;
    CanonBuilder b;
    b.tool(1, 2.0).line(0, 0, -2);
    b.feed(simulation);
    simulation.finish();
    EXPECT_FALSE(simulation.hasStock());
    EXPECT_EQ(simulation.removedVolumeMm3(), 0.0);
    EXPECT_EQ(simulation.notes().size(), 1u);
}

TEST(ProgressiveStock, PublishesSnapshotsWithoutBlockingTheCaller) {
    StockOptions options;
    ProgressiveStock progressive(options, 128, std::chrono::milliseconds(10));
    EXPECT_EQ(progressive.latest()->mesh, nullptr);
    CanonBuilder b;
    b.box(Vec3(0, 0, -10), Vec3(100, 100, 0)).tool(1, 3.0).rapid(0, 0, 5);
    for (int row = 0; row < 50; ++row) {
        b.line(0, row * 2.0, -1)
            .line(100, row * 2.0, -1)
            .rapid(100, row * 2.0, 5)
            .rapid(0, row * 2.0 + 2, 5);
    }
    const auto start = std::chrono::steady_clock::now();
    for (const auto& command : b.commands)
        progressive.push(command);
    progressive.finish();
    const auto pushTime = std::chrono::steady_clock::now() - start;
    // Pushing is a queue insertion: far below the simulation time.
    EXPECT_LT(std::chrono::duration<double>(pushTime).count(), 0.5);
    ASSERT_TRUE(progressive.waitFinished(std::chrono::seconds(60)));
    const auto last = progressive.latest();
    EXPECT_TRUE(last->finished);
    ASSERT_NE(last->mesh, nullptr);
    EXPECT_GT(last->mesh->triangleCount(), 0u);
    // 50 grooves 6 mm wide (overlapping rows 2 mm apart) 1 mm deep: 100 x 104-ish area.
    EXPECT_GT(last->removedVolumeMm3, 0.9 * 100 * 100);
    EXPECT_EQ(progressive.pendingCommands(), 0u);
}

}  // namespace
}  // namespace kerf::graphics
