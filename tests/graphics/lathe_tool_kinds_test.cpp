// Drills and grooving tools in the lathe stock: the material they remove is their own shape, not
// a turning insert with a solid holder beside it. Volumes are those of the cylinders, cones and
// rings the tools sweep, computed by hand; the grid (cells of 0.05 mm, rings of 2 pi r dr dz) is
// exact where an edge lies on a cell border and within 0.2 % along a drill's point.
#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"
#include "graphics/stock/cutter.h"
#include "graphics/stock/lathe_stock.h"

namespace kerf::graphics {
namespace {

constexpr double kCell = 0.05;

LatheBar barR25() {
    LatheBar bar;
    bar.radiusMm = 25;
    bar.zMin = -60;
    bar.zMax = 0;
    return bar;
}

bool materialAt(const LatheStock& stock, double r, double z) {
    return stock.material(static_cast<int>(r / kCell),
                          static_cast<int>((z - stock.bar().zMin) / kCell));
}

LatheInsert tool(LatheToolKind kind, int code, double width) {
    LatheInsert insert;
    insert.kind = kind;
    insert.locationCode = code;
    insert.noseRadiusMm = 0.0;
    insert.widthMm = width;
    return insert;
}

TEST(LatheToolKinds, TheOffsetAndTheCuttingWidthNameTheTool) {
    canon::ToolGeometry g;
    g.locationCode = 0;
    g.cuttingWidthMm = 8;
    EXPECT_EQ(LatheInsert::fromGeometry(g).kind, LatheToolKind::Drill);
    g.locationCode = 9;
    EXPECT_EQ(LatheInsert::fromGeometry(g).kind, LatheToolKind::Drill);
    EXPECT_DOUBLE_EQ(LatheInsert::fromGeometry(g).widthMm, 8.0);
    g.locationCode = 3;
    EXPECT_EQ(LatheInsert::fromGeometry(g).kind, LatheToolKind::Grooving);
    g.locationCode = 2;
    EXPECT_TRUE(LatheInsert::fromGeometry(g).groovesAlongZ());
    g.locationCode = 5;
    EXPECT_FALSE(LatheInsert::fromGeometry(g).groovesAlongZ());
    g.cuttingWidthMm = 0;  // no NOSEW: a turning insert of nose R at its code
    g.radiusMm = 0.8;
    const LatheInsert turning = LatheInsert::fromGeometry(g);
    EXPECT_EQ(turning.kind, LatheToolKind::Turning);
    EXPECT_EQ(turning.locationCode, 5);
    EXPECT_DOUBLE_EQ(turning.noseRadiusMm, 0.8);
    g.locationCode = -1;  // a milling tool's geometry
    g.cuttingWidthMm = 8;
    EXPECT_EQ(LatheInsert::fromGeometry(g).kind, LatheToolKind::Turning);
}

// Length of a drill point of included angle `angleDeg` on a drill of radius r.
double pointLength(double r, double angleDeg) {
    return r / std::tan(angleDeg * kPi / 360.0);
}

TEST(LatheToolKinds, ADrillOnTheAxisBoresAHoleWithTheConeOfItsPoint) {
    // A D8 drill (118 degree point, no NOSEA) from Z2 to Z-25 and back at X0: the point's tip
    // reaches Z-25, the full diameter Z-25 + h, h = 4 / tan 59 = 2.4034. The hole is the
    // cylinder r 0..4 down to Z-25 + h and the cone below it: pi 4^2 (25 - h) + pi 4^2 h / 3.
    LatheStock stock(barR25(), kCell, 50'000'000);
    const LatheInsert drill = tool(LatheToolKind::Drill, 0, 8.0);
    EXPECT_DOUBLE_EQ(drill.pointAngleDeg, 118.0);
    EXPECT_TRUE(stock.cut(0, 2, 0, -25, drill));
    stock.cut(0, -25, 0, 2, drill);
    const double h = pointLength(4, 118);
    const double hole = kPi * 16 * (25 - h) + kPi * 16 * h / 3;
    EXPECT_NEAR(stock.removedVolumeMm3(), hole, 2e-3 * hole);
    EXPECT_FALSE(materialAt(stock, 3.9, -10));
    EXPECT_TRUE(materialAt(stock, 4.1, -10));    // the wall of the hole
    EXPECT_TRUE(materialAt(stock, 24.9, -1));    // the bar around it
    EXPECT_TRUE(materialAt(stock, 0.1, -25.1));  // below the tip
    // Half way up the point (1.2 above the tip) the cone's radius is 1.2 tan 59 = 1.997.
    EXPECT_FALSE(materialAt(stock, 1.8, -23.8));
    EXPECT_TRUE(materialAt(stock, 2.2, -23.8));
    EXPECT_TRUE(materialAt(stock, 3.9, -25 + h - 0.2));  // the corner a flat drill would cut
}

TEST(LatheToolKinds, TheDrillPointIsTheNoseAngleOfItsToolChange) {
    // A drill (centre code, NOSEW8) whose tool change carries NOSEA 90: the point is as long as
    // the drill's radius, h = 4, and the hole to Z-20 holds pi 4^2 (20 - 4) + pi 4^2 4 / 3.
    // Without a nose angle: 118.
    canon::ToolGeometry g;
    g.locationCode = 0;
    g.cuttingWidthMm = 8;
    g.noseAngleDeg = 90;
    const LatheInsert drill = LatheInsert::fromGeometry(g);
    EXPECT_DOUBLE_EQ(drill.pointAngleDeg, 90.0);
    LatheStock stock(barR25(), kCell, 50'000'000);
    stock.cut(0, 2, 0, -20, drill);
    const double hole = kPi * 16 * (20 - 4) + kPi * 16 * 4.0 / 3;
    EXPECT_NEAR(stock.removedVolumeMm3(), hole, 2e-3 * hole);
    EXPECT_TRUE(materialAt(stock, 3.1, -17.1));  // 2.9 above the tip the cone is 2.9 wide
    EXPECT_FALSE(materialAt(stock, 2.7, -17.1));
    g.noseAngleDeg = 0;
    EXPECT_DOUBLE_EQ(LatheInsert::fromGeometry(g).pointAngleDeg, 118.0);
    // A turning insert keeps its nose angle to itself: it has no point.
    g.cuttingWidthMm = 0;
    g.locationCode = 3;
    g.noseAngleDeg = 55;
    EXPECT_EQ(LatheInsert::fromGeometry(g).kind, LatheToolKind::Turning);
}

TEST(LatheToolKinds, ADrillOffTheAxisCutsTheRingItSweepsAsThePartTurns) {
    // A D6 drill at X10 to Z-5: the part turns, so it clears r 7..13, the point's cone
    // (h = 3 / tan 59) at the bottom. The section is symmetric about r 10, so the volume is
    // 2 pi 10 times its area 6 (5 - h) + 6 h / 2.
    LatheStock stock(barR25(), kCell, 50'000'000);
    stock.cut(10, 2, 10, -5, tool(LatheToolKind::Drill, 9, 6.0));
    const double h = pointLength(3, 118);
    const double ring = 2 * kPi * 10 * (6 * (5 - h) + 3 * h);
    EXPECT_NEAR(stock.removedVolumeMm3(), ring, 2e-3 * ring);
    EXPECT_TRUE(materialAt(stock, 6.9, -1));
    EXPECT_TRUE(materialAt(stock, 13.1, -1));
    EXPECT_FALSE(materialAt(stock, 10, -4.9));
    EXPECT_TRUE(materialAt(stock, 7.1, -4.9));
}

TEST(LatheToolKinds, AGroovingBladeCutsItsWidth) {
    // Blades 3 wide plunging from X27 to X21. Code 3 (programmed point at the blade's -Z corner)
    // at Z-13: the ring r 21..25, z -13..-10. Code 5 (at its +Z corner) at Z-30: z -33..-30.
    // Each pi (25^2 - 21^2) 3 = 552 pi; the holder above the blade clears nothing more.
    LatheStock stock(barR25(), kCell, 50'000'000);
    stock.cut(27, -13, 21, -13, tool(LatheToolKind::Grooving, 3, 3.0));
    EXPECT_NEAR(stock.removedVolumeMm3(), 552 * kPi, 1e-6 * 552 * kPi);
    EXPECT_FALSE(materialAt(stock, 22, -11.5));
    EXPECT_TRUE(materialAt(stock, 22, -9.9));
    EXPECT_TRUE(materialAt(stock, 22, -13.1));
    EXPECT_TRUE(materialAt(stock, 20.9, -11.5));
    stock.cut(27, -30, 21, -30, tool(LatheToolKind::Grooving, 5, 3.0));
    EXPECT_NEAR(stock.removedVolumeMm3(), 2 * 552 * kPi, 2e-6 * 552 * kPi);
    EXPECT_FALSE(materialAt(stock, 22, -32.9));
    EXPECT_TRUE(materialAt(stock, 22, -29.9));
}

TEST(LatheToolKinds, AFaceGroovingBladeCutsAnAnnulusIntoTheFace) {
    // Code 2 (edge facing -Z), 3 wide outwards from X10, plunging from Z2 to Z-3: the annulus
    // r 10..13, z -3..0, pi (13^2 - 10^2) 3 = 207 pi; the material outside it stays.
    LatheStock stock(barR25(), kCell, 50'000'000);
    stock.cut(10, 2, 10, -3, tool(LatheToolKind::Grooving, 2, 3.0));
    EXPECT_NEAR(stock.removedVolumeMm3(), 207 * kPi, 1e-6 * 207 * kPi);
    EXPECT_TRUE(materialAt(stock, 14, -1));
    EXPECT_TRUE(materialAt(stock, 9.9, -1));
    EXPECT_FALSE(materialAt(stock, 12.9, -2.9));
    EXPECT_TRUE(materialAt(stock, 11, -3.1));
}

}  // namespace
}  // namespace kerf::graphics
