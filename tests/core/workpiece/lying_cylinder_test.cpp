// A cylinder blank lying along X or Y (BLK FORM CYLINDER X|Y, an A or B table's part): touches and
// rapid collisions, with and without the setup error. Expected values from the geometry by hand.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/canon/commands.h"
#include "core/workpiece/blank_solids.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {
namespace {

constexpr double kBall = 2.0;
const double kAngle = 0.7 * std::numbers::pi / 180.0;
const Vec3 kShift(1.5, -0.8, -0.2);

// BLK FORM CYLINDER <axis> R25 L90 DIST+80: along the axis from -10 to 80, through the origin.
SimulatedWorkpiece lyingCylinder(Axis axis, Placement placement = {}) {
    canon::StockDefinition stock;
    canon::StockCylinder cylinder;
    cylinder.axis = axis;
    cylinder.radiusMm = 25.0;
    cylinder.lengthMm = 90.0;
    cylinder.distanceMm = 80.0;
    stock.shape = cylinder;
    SimulatedWorkpiece part(placement);
    for (const Solid& solid : blankSolids(stock))
        part.add(solid);
    return part;
}

TEST(LyingCylinder, AlongXTheBallStopsOneRadiusOutsideTheMantleAndTheEndFace) {
    const SimulatedWorkpiece part = lyingCylinder(Axis::X);
    ASSERT_FALSE(part.empty());
    // Over the axis from above: the mantle's top at Z 25.
    auto hit = part.touch(Vec3(30, 0, 40), Vec3(0, 0, -1), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z(), 27.0, 1e-9);
    // 15 beside the axis: the ball centre meets the circle of radius 27 at z = sqrt(27^2 - 15^2).
    hit = part.touch(Vec3(30, 15, 40), Vec3(0, 0, -1), 30.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z(), std::sqrt(27.0 * 27.0 - 15.0 * 15.0), 1e-8);
    // From the side and onto the end face at X 80; beyond the end face at X -10 nothing.
    hit = part.touch(Vec3(30, 40, 0), Vec3(0, -1, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->y(), 27.0, 1e-9);
    hit = part.touch(Vec3(100, 0, 0), Vec3(-1, 0, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), 82.0, 1e-9);
    EXPECT_FALSE(part.touch(Vec3(-13, 0, 40), Vec3(0, 0, -1), 60.0, kBall));
    EXPECT_TRUE(part.touches(Vec3(0, 0, 26), kBall));
    EXPECT_FALSE(part.touches(Vec3(0, 0, 27.5), kBall));
}

TEST(LyingCylinder, AlongYTheCentreLiesInXAndZ) {
    const SimulatedWorkpiece part = lyingCylinder(Axis::Y);
    auto hit = part.touch(Vec3(40, 30, 0), Vec3(-1, 0, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), 27.0, 1e-9);
    hit = part.touch(Vec3(0, 100, 0), Vec3(0, -1, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->y(), 82.0, 1e-9);
    // Beyond the end face Y -10 a touch along -X misses.
    EXPECT_FALSE(part.touch(Vec3(40, -20, 0), Vec3(-1, 0, 0), 60.0, kBall));
}

TEST(LyingCylinder, SetupErrorTurnsTheAxisAboutZAndShiftsIt) {
    // The axis runs through (1.5, -0.8, -0.2) along (cos a, sin a, 0). A ball centre P lies
    // 27 from it when its offset square to the axis, horizontal h = -(x - 1.5) sin a + (y + 0.8)
    // cos a and vertical z + 0.2, has length 27.
    const SimulatedWorkpiece part = lyingCylinder(Axis::X, {kShift, 0.7});
    const double s = std::sin(kAngle), c = std::cos(kAngle);
    // From above at X 30 Y 0.
    const double h = -28.5 * s + 0.8 * c;
    auto hit = part.touch(Vec3(30, 0, 40), Vec3(0, 0, -1), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z(), -0.2 + std::sqrt(27.0 * 27.0 - h * h), 1e-8);
    // From +Y at X 30 Z 0: h = sqrt(27^2 - 0.2^2).
    hit = part.touch(Vec3(30, 40, 0), Vec3(0, -1, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->y(), (std::sqrt(27.0 * 27.0 - 0.04) + 28.5 * s) / c - 0.8, 1e-8);
    // The end face X 80 turned and shifted: the ball centre at Y 0 Z 0 stops 2 outside its
    // plane, where (x - 1.5) cos a + 0.8 sin a = 82.
    hit = part.touch(Vec3(100, 0, 0), Vec3(-1, 0, 0), 20.0, kBall);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), 1.5 + (82.0 - 0.8 * s) / c, 1e-8);
}

TEST(LyingCylinder, RapidsAcrossItAreCollisionsAboveItNot) {
    const Cutter d10{5.0, 0.0, 60.0};
    const SimulatedWorkpiece part = lyingCylinder(Axis::X);
    // Across the axis 1 mm above the mantle's top (Z 25): free; at Z 20 the end face (tip disc
    // of radius 5) cuts the mantle, whose half-width there is sqrt(25^2 - 20^2) = 15.
    EXPECT_FALSE(part.rapidTakesMaterial(d10, Vec3(30, -60, 26), Vec3(30, 60, 26)));
    EXPECT_TRUE(part.rapidTakesMaterial(d10, Vec3(30, -60, 20), Vec3(30, 60, 20)));
    // Along Y beside the end face X 80: the rim stays outside at X 86, not at X 84.
    EXPECT_FALSE(part.rapidTakesMaterial(d10, Vec3(86, -60, 0), Vec3(86, 60, 0)));
    EXPECT_TRUE(part.rapidTakesMaterial(d10, Vec3(84, -60, 0), Vec3(84, 60, 0)));
    // With the setup error the part lies 0.2 lower: a rapid at Z 24.9 over it is free there.
    const SimulatedWorkpiece placed = lyingCylinder(Axis::X, {kShift, 0.7});
    EXPECT_TRUE(part.rapidTakesMaterial(d10, Vec3(1.5, -60, 24.9), Vec3(1.5, 60, 24.9)));
    EXPECT_FALSE(placed.rapidTakesMaterial(d10, Vec3(1.5, -60, 24.9), Vec3(1.5, 60, 24.9)));
}

}  // namespace
}  // namespace kerf::workpiece
