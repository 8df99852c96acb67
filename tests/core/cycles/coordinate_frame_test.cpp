#include "core/cycles/transform/coordinate_frame.h"

#include <gtest/gtest.h>

#include "core/cycles/transform/transformation_cycles.h"

namespace kerf::cycles {
namespace {

Pose xyz(double x, double y, double z) {
    Pose p;
    p.setXyz({x, y, z});
    return p;
}

TEST(CoordinateFrame, ScaleRotateMirrorShiftInThisOrder) {
    CoordinateFrame f;
    f.setShift(Axis::X, 50.0, false);
    f.setRotation(90.0, false, Plane::XY);
    f.setMirror(axisBit(Axis::X));
    f.setScale(0.5);
    // (10, 0, -2) -> scale (5, 0, -1) -> rotate (0, 5) -> mirror X (0, 5) -> shift (50, 5).
    Pose w = f.toWorkpiece(xyz(10.0, 0.0, -2.0));
    EXPECT_NEAR(w[Axis::X], 50.0, 1e-12);
    EXPECT_NEAR(w[Axis::Y], 5.0, 1e-12);
    EXPECT_NEAR(w[Axis::Z], -1.0, 1e-12);
    Pose back = f.toProgram(w);
    EXPECT_NEAR(back[Axis::X], 10.0, 1e-12);
    EXPECT_NEAR(back[Axis::Y], 0.0, 1e-12);
    EXPECT_NEAR(back[Axis::Z], -2.0, 1e-12);
    EXPECT_TRUE(f.flipsOrientation(Plane::XY));
    EXPECT_FALSE(f.keepsArcs(Plane::ZX));  // rotated about Z
}

// The tilt sits between the datum shift and the preset, the tables' turn outermost. A shift made
// before the tilt stays in the untilted system, one made after it acts along the tilted axes.
TEST(CoordinateFrame, TiltAndTableTurnComposeWithTheShift) {
    // About Y by +90: tilted X = (0, 0, -1), tilted Z = (1, 0, 0).
    Eigen::Matrix3d tilt;
    tilt << 0, 0, 1, 0, 1, 0, -1, 0, 0;
    CoordinateFrame f;
    f.setShift(Axis::X, 20.0, false);
    f.setTilt(tilt);
    f.setShift(Axis::X, 5.0, false);  // along the tilted X: the part's -Z
    // (1, 2, 3) + (5, 0, 0) = (6, 2, 3); tilted: (3, 2, -6); + (20, 0, 0).
    Pose w = f.toWorkpiece(xyz(1.0, 2.0, 3.0));
    EXPECT_NEAR(w[Axis::X], 23.0, 1e-12);
    EXPECT_NEAR(w[Axis::Y], 2.0, 1e-12);
    EXPECT_NEAR(w[Axis::Z], -6.0, 1e-12);
    // The table turns the part back by Ry(-90) and moves it by (1, 0, 0): (-z, y, x) + (1, 0, 0).
    f.setTable(tilt.transpose(), Vec3(1.0, 0.0, 0.0));
    w = f.toWorkpiece(xyz(1.0, 2.0, 3.0));
    EXPECT_NEAR(w[Axis::X], 7.0, 1e-12);
    EXPECT_NEAR(w[Axis::Y], 2.0, 1e-12);
    EXPECT_NEAR(w[Axis::Z], 23.0, 1e-12);
    const Pose back = f.toProgram(w);
    EXPECT_NEAR(back[Axis::X], 1.0, 1e-12);
    EXPECT_NEAR(back[Axis::Y], 2.0, 1e-12);
    EXPECT_NEAR(back[Axis::Z], 3.0, 1e-12);
    // Table and tilt cancel: arcs of every plane stay arcs, none turns over.
    EXPECT_TRUE(f.keepsArcs(Plane::XY));
    EXPECT_FALSE(f.flipsOrientation(Plane::XY));
    // Without the table's turn the XY plane stands upright: no arcs in it.
    f.setTable(Eigen::Matrix3d::Identity(), Vec3::Zero());
    EXPECT_FALSE(f.keepsArcs(Plane::XY));
    EXPECT_TRUE(f.keepsArcs(Plane::ZX));
    // Untilting keeps the tilted shift, turned back: 20 along X and 5 along the part's -Z.
    f.clearTilt();
    EXPECT_NEAR(f.shift()[Axis::X], 20.0, 1e-12);
    EXPECT_NEAR(f.shift()[Axis::Z], -5.0, 1e-12);
    EXPECT_FALSE(f.tilted());
}

TEST(CoordinateFrame, AxisScalingAboutItsCentre) {
    CoordinateFrame f;
    CycleWords words = {
        {"X", false, 1.4}, {"Y", false, 0.6}, {"CCX", false, 15.0}, {"CCY", false, 20.0}};
    ASSERT_FALSE(applyAxisScaling(f, words));
    Pose w = f.toWorkpiece(xyz(25.0, 30.0, 0.0));
    EXPECT_NEAR(w[Axis::X], 15.0 + 1.4 * 10.0, 1e-12);
    EXPECT_NEAR(w[Axis::Y], 20.0 + 0.6 * 10.0, 1e-12);
    EXPECT_FALSE(f.keepsArcs(Plane::XY));  // different factors in the plane
}

TEST(CoordinateFrame, IncrementalShiftAndRotationAdd) {
    CoordinateFrame f;
    ASSERT_FALSE(applyDatumShift(f, {{"X", false, 10.0}, {"X", true, 5.0}}));
    EXPECT_DOUBLE_EQ(f.shift()[Axis::X], 15.0);
    ASSERT_FALSE(applyRotation(f, {{"ROT", false, 30.0}, {"ROT", true, 15.0}}, Plane::XY));
    EXPECT_DOUBLE_EQ(f.rotationDeg(), 45.0);
    EXPECT_TRUE(applyRotation(f, {{"ROT", false, 400.0}}, Plane::XY));
}

TEST(CoordinateFrame, ScalingFactorRangeAndMirrorOfTheToolAxis) {
    CoordinateFrame f;
    EXPECT_TRUE(applyScaling(f, {{"SCL", false, 0.0}}));
    EXPECT_TRUE(applyScaling(f, {{"SCL", false, 100.0}}));
    bool ignored = false;
    ASSERT_FALSE(applyMirror(f, {{"X", false, {}}, {"Z", false, {}}}, Axis::Z, ignored));
    EXPECT_TRUE(ignored);
    EXPECT_EQ(f.mirror(), axisBit(Axis::X));
}

TEST(CoordinateFrame, PresetClearsTheOtherTransformations) {
    CoordinateFrame f;
    f.setShift(Axis::X, 10.0, false);
    f.setScale(2.0);
    Pose offset;
    offset[Axis::Y] = 7.0;
    f.setPreset(offset);
    Pose w = f.toWorkpiece(xyz(1.0, 1.0, 1.0));
    EXPECT_DOUBLE_EQ(w[Axis::X], 1.0);
    EXPECT_DOUBLE_EQ(w[Axis::Y], 8.0);
}

TEST(CoordinateFrame, PointShiftOfCycle12ActsFirstAndOutlivesAPreset) {
    CoordinateFrame f;
    f.setRotation(90.0, false, Plane::XY);
    f.setPointShift(xyz(10.0, 0.0, -5.0));
    // (0, 0, 2) + point (10, 0, -5) = (10, 0, -3), then rotated by 90 degrees: (0, 10, -3).
    Pose w = f.toWorkpiece(xyz(0.0, 0.0, 2.0));
    EXPECT_NEAR(w[Axis::X], 0.0, 1e-12);
    EXPECT_NEAR(w[Axis::Y], 10.0, 1e-12);
    EXPECT_NEAR(w[Axis::Z], -3.0, 1e-12);
    Pose back = f.toProgram(w);
    EXPECT_NEAR(back[Axis::X], 0.0, 1e-12);
    EXPECT_NEAR(back[Axis::Z], 2.0, 1e-12);
    EXPECT_FALSE(f.identity());
    f.setPreset(Pose{});  // cycle 247 inside the called program keeps the point's shift
    EXPECT_DOUBLE_EQ(f.toWorkpiece(xyz(1.0, 0.0, 0.0))[Axis::X], 11.0);
}

// identity() is kept by the setters (the interpreter asks for every block): each one that makes
// a transformation active clears it, and undoing the transformation sets it again.
TEST(CoordinateFrame, IdentityFollowsEverySetter) {
    CoordinateFrame f;
    EXPECT_TRUE(f.identity());
    f.setShift(Axis::Y, 5.0, false);
    EXPECT_FALSE(f.identity());
    f.setShift(Axis::Y, -5.0, true);
    EXPECT_TRUE(f.identity());
    f.setMirror(axisBit(Axis::X));
    EXPECT_FALSE(f.identity());
    f.setMirror(0);
    EXPECT_TRUE(f.identity());
    f.setRotation(30.0, false, Plane::XY);
    EXPECT_FALSE(f.identity());
    f.setRotation(-30.0, true, Plane::XY);
    EXPECT_TRUE(f.identity());
    f.setScale(0.5);
    EXPECT_FALSE(f.identity());
    f.setScale(1.0);
    EXPECT_TRUE(f.identity());
    f.setAxisScale(Axis::Z, 2.0);
    EXPECT_FALSE(f.identity());
    f.setAxisScale(Axis::Z, 1.0);
    EXPECT_TRUE(f.identity());
    f.setPointShift(xyz(0.0, 0.0, 1.0));
    EXPECT_FALSE(f.identity());
    f.setPointShift(Pose{});
    EXPECT_TRUE(f.identity());
    f.addTurns(Axis::C, 360.0);
    EXPECT_FALSE(f.identity());
    f.addTurns(Axis::C, -360.0);
    EXPECT_TRUE(f.identity());
    f.setTilt(Eigen::Matrix3d::Identity());
    EXPECT_FALSE(f.identity());
    f.clearTilt();
    EXPECT_TRUE(f.identity());
    f.setTable(Eigen::Matrix3d::Identity(), Vec3(0.0, 0.0, 3.0));
    EXPECT_FALSE(f.identity());
    f.setTable(Eigen::Matrix3d::Identity(), Vec3::Zero());
    EXPECT_TRUE(f.identity());
    f.setShift(Axis::X, 1.0, false);
    Pose offset;
    offset[Axis::X] = 2.0;
    f.setPreset(offset);  // clears the shift, but is itself a transformation
    EXPECT_FALSE(f.identity());
    f.setPreset(Pose{});
    EXPECT_TRUE(f.identity());
    // A copy keeps the answer of the frame it copies.
    f.setScale(3.0);
    const CoordinateFrame copy = f;
    EXPECT_FALSE(copy.identity());
}

}  // namespace
}  // namespace kerf::cycles
