// The voxel stock against analytic volumes: tilted and horizontal tools, by hand.
#include "graphics/stock/voxel_stock.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace kerf::graphics {
namespace {

constexpr double kPi = std::numbers::pi;

MillCutter flat(double r) {
    return MillCutter::fromGeometry(r, 0.0);
}

TEST(VoxelStock, BlankHoldsTheBoxVolume) {
    VoxelStock stock({-5.0, 0.0, -2.0}, {5.0, 20.0, 3.0}, 0.1, 64'000'000);
    EXPECT_EQ(stock.cellsX(), 100);
    EXPECT_EQ(stock.cellsY(), 200);
    EXPECT_EQ(stock.cellsZ(), 50);
    EXPECT_NEAR(stock.volumeMm3(), 1000.0, 1e-6);
    EXPECT_TRUE(stock.solidAt({0.0, 10.0, 0.0}));
    EXPECT_FALSE(stock.solidAt({0.0, 10.0, 3.5}));
}

TEST(VoxelStock, CellGrowsToStayWithinTheBudget) {
    VoxelStock stock({0.0, 0.0, 0.0}, {100.0, 100.0, 100.0}, 0.1, 1'000'000);
    EXPECT_NEAR(stock.cellMm(), 1.0, 0.01);
    EXPECT_LE(static_cast<double>(stock.cellsX()) * stock.cellsY() * stock.cellsZ(), 1e6);
}

// A flat R2.5 tool tilted 45 deg about Y plunges along its axis into the top face (z = 0) until
// its tip is 8 mm below the point it entered at (along the axis). The hole is a cylinder cut square
// at the tip and obliquely by the top face; the oblique cut averages to the length at the axis
// (it is linear across the disc), so the volume is pi R^2 8 = 157.08 mm^3, as long as the top face
// does not reach the tip's disc (8 cos 45 > 2.5 sin 45).
TEST(VoxelStock, TiltedFlatToolPlungeRemovesTheAnalyticCylinder) {
    VoxelStock stock({-15.0, -10.0, -15.0}, {15.0, 10.0, 0.0}, 0.1, 64'000'000);
    const double before = stock.volumeMm3();
    const Vec3 u(std::sqrt(0.5), 0.0, std::sqrt(0.5));
    ASSERT_TRUE(stock.cut(10.0 * u, -8.0 * u, u, flat(2.5)));
    const double expected = kPi * 2.5 * 2.5 * 8.0;
    EXPECT_NEAR(before - stock.volumeMm3(), expected, 0.01 * expected);
    // On the axis 4 mm down: air; beyond the tip and beside the hole: material.
    EXPECT_FALSE(stock.solidAt(-4.0 * u));
    EXPECT_TRUE(stock.solidAt(-9.0 * u));
    EXPECT_TRUE(stock.solidAt(-4.0 * u + Vec3(0.0, 3.0, 0.0)));
}

// A ball R3 with its axis along +X plunges into the side face x = 0 to 6 mm: a cylinder of
// length 6 - 3 and a half ball, pi 9 3 + 2/3 pi 27 = 141.37 mm^3.
TEST(VoxelStock, HorizontalBallPlungeIntoASideFace) {
    VoxelStock stock({-20.0, -10.0, -20.0}, {0.0, 10.0, 0.0}, 0.1, 64'000'000);
    const double before = stock.volumeMm3();
    const MillCutter ball = MillCutter::fromGeometry(3.0, 3.0);
    ASSERT_TRUE(stock.cut({10.0, 0.0, -10.0}, {-6.0, 0.0, -10.0}, Vec3::UnitX(), ball));
    const double expected = kPi * 9.0 * 3.0 + 2.0 / 3.0 * kPi * 27.0;
    EXPECT_NEAR(before - stock.volumeMm3(), expected, 0.01 * expected);
    EXPECT_FALSE(stock.solidAt({-5.8, 0.0, -10.0}));  // inside the ball's tip
    EXPECT_TRUE(stock.solidAt({-5.8, 2.0, -10.0}));   // beside it: the ball curves away
    EXPECT_FALSE(stock.solidAt({-2.0, 2.9, -10.0}));  // the cylinder's side
}

// A flat R2 tool lying along +X cuts a slot 3 mm deep into the side face x = 0: plunge at y -5,
// then 10 mm along Y. Seen on the face the slot is a stadium (a 4 x 10 rectangle and a disc of
// R2): (40 + 4 pi) 3 = 157.70 mm^3.
TEST(VoxelStock, SideMillingWithAHorizontalToolCutsTheStadium) {
    VoxelStock stock({-20.0, -10.0, -15.0}, {0.0, 10.0, 0.0}, 0.1, 64'000'000);
    const double before = stock.volumeMm3();
    ASSERT_TRUE(stock.cut({10.0, -5.0, -5.0}, {-3.0, -5.0, -5.0}, Vec3::UnitX(), flat(2.0)));
    ASSERT_TRUE(stock.cut({-3.0, -5.0, -5.0}, {-3.0, 5.0, -5.0}, Vec3::UnitX(), flat(2.0)));
    const double expected = (40.0 + 4.0 * kPi) * 3.0;
    EXPECT_NEAR(before - stock.volumeMm3(), expected, 0.01 * expected);
}

// A drill (118 deg point) standing upside down (its axis along -Z) plunges 10 mm up into the
// bottom face z = 0: any direction works, the point's cone included.
TEST(VoxelStock, DrillPointIntoTheBottomFace) {
    VoxelStock stock({-10.0, -10.0, 0.0}, {10.0, 10.0, 20.0}, 0.1, 64'000'000);
    const double before = stock.volumeMm3();
    const MillCutter drill = MillCutter::fromGeometry(2.5, 0.0, 118.0);
    ASSERT_EQ(drill.kind, CutterKind::Drill);
    ASSERT_TRUE(stock.cut({0.0, 0.0, -5.0}, {0.0, 0.0, 10.0}, -Vec3::UnitZ(), drill));
    // The cone reaches R at 2.5 / tan 59 = 1.5021 mm: a cone and the cylinder above it.
    const double cone = 2.5 / std::tan(59.0 * kPi / 180.0);
    const double expected = kPi * 6.25 * cone / 3.0 + kPi * 6.25 * (10.0 - cone);
    EXPECT_NEAR(before - stock.volumeMm3(), expected, 0.01 * expected);
}

TEST(VoxelStock, TakesOverAHeightFieldsMaterial) {
    HeightFieldStock field({0.0, 0.0, -10.0}, {20.0, 20.0, 0.0}, 0.1, 25'000'000);
    field.cut({10.0, 10.0, 5.0}, {10.0, 10.0, -4.0}, flat(3.0));
    const VoxelStock voxels = VoxelStock::fromHeightField(field, 64'000'000);
    EXPECT_NEAR(voxels.cellMm(), 0.1, 1e-9);
    EXPECT_NEAR(voxels.volumeMm3(), field.volumeMm3(), 0.005 * field.volumeMm3());
    EXPECT_FALSE(voxels.solidAt({10.0, 10.0, -2.0}));
    EXPECT_TRUE(voxels.solidAt({10.0, 10.0, -6.0}));
}

// The mesh of a box with a through hole is closed: its volume is the voxels' (one cube a cell).
TEST(VoxelStock, MeshEnclosesTheMaterial) {
    VoxelStock stock({0.0, 0.0, 0.0}, {10.0, 10.0, 5.0}, 0.25, 64'000'000);
    stock.cut({5.0, 5.0, 10.0}, {5.0, 5.0, -10.0}, Vec3::UnitZ(), flat(2.0));
    const Mesh mesh = stock.mesh(200);
    EXPECT_GT(mesh.triangleCount(), 12u);
    EXPECT_NEAR(mesh.signedVolume(), stock.volumeMm3(), 1e-3);
}

}  // namespace
}  // namespace kerf::graphics
