#include "core/workpiece/simulated_workpiece.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace kerf::workpiece {
namespace {

constexpr double kRadius = 2.0;

SimulatedWorkpiece blankBox(Placement placement = {}) {
    SimulatedWorkpiece part(placement);
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    return part;
}

TEST(SimulatedWorkpiece, BallTouchesAFaceOneRadiusAwayFromIt) {
    const SimulatedWorkpiece part = blankBox();
    auto hit = part.touch(Vec3(-10, 30, -5), Vec3(1, 0, 0), 20.0, kRadius);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), -2.0, 1e-9);
    EXPECT_NEAR(hit->y(), 30.0, 1e-12);
    // The top face from above.
    hit = part.touch(Vec3(50, 30, 10), Vec3(0, 0, -1), 20.0, kRadius);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z(), 2.0, 1e-9);
}

TEST(SimulatedWorkpiece, NothingWithinTheMeasuringPathIsAMiss) {
    const SimulatedWorkpiece part = blankBox();
    EXPECT_FALSE(part.touch(Vec3(-10, 30, -5), Vec3(1, 0, 0), 7.9, kRadius));
    EXPECT_FALSE(part.touch(Vec3(-10, 30, -5), Vec3(-1, 0, 0), 100.0, kRadius));
    EXPECT_FALSE(SimulatedWorkpiece{}.touch(Vec3(0, 0, 0), Vec3(1, 0, 0), 100.0, kRadius));
}

TEST(SimulatedWorkpiece, SetupErrorShiftsAndTurnsThePartAboutItsProgrammedOrigin) {
    const double a = 0.7 * std::numbers::pi / 180.0;
    const SimulatedWorkpiece part = blankBox({Vec3(1.5, -0.8, -0.2), 0.7});
    // The left face x = 0 turned by 0.7 degrees about the origin and shifted: at height y it
    // lies at x = 1.5 - (y + 0.8) tan(a).
    auto hit = part.touch(Vec3(-10, 30, -5), Vec3(1, 0, 0), 20.0, kRadius);
    ASSERT_TRUE(hit);
    // The ball touches the tilted face: its centre is r / cos(a) short of the face along x.
    EXPECT_NEAR(hit->x(), 1.5 - 30.8 * std::tan(a) - kRadius / std::cos(a), 1e-9);
    hit = part.touch(Vec3(50, 30, 10), Vec3(0, 0, -1), 20.0, kRadius);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z(), -0.2 + kRadius, 1e-9);
}

TEST(SimulatedWorkpiece, HoleWallsAndStudsAreTouchedFromInsideAndOutside) {
    SimulatedWorkpiece part({Vec3(1.5, -0.8, 0.0), 0.0});
    part.add({Box{Vec3(-50, -50, -40), Vec3(50, 50, 0)}, true});
    part.add({Cylinder{Vec2(0, 0), 15.0, -30.0, 1.0}, false});
    auto hit = part.touch(Vec3(1.5, -0.8, -5), Vec3(0, 1, 0), 20.0, kRadius);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->y(), -0.8 + 15.0 - kRadius, 1e-9);
    EXPECT_TRUE(part.touches(Vec3(1.5, -0.8, -35), kRadius));  // below the hole's bottom
    EXPECT_FALSE(part.touches(Vec3(1.5, -0.8, -5), kRadius));

    SimulatedWorkpiece stud;
    stud.add({Cylinder{Vec2(0, 0), 25.0, -20.0, 0.0}, true});
    hit = stud.touch(Vec3(40, 0, -5), Vec3(-1, 0, 0), 20.0, kRadius);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), 25.0 + kRadius, 1e-9);
}

}  // namespace
}  // namespace kerf::workpiece
