#include "core/machine/workpiece_frame.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"

namespace kerf::machine {
namespace {

constexpr double kEps = 1e-6;

MachineConfig load(std::string_view name) {
    DiagnosticList problems;
    Expected<MachineConfig> config = loadMachine(name, &problems);
    EXPECT_TRUE(config.ok() && problems.empty());
    return config.ok() ? *config : MachineConfig{};
}

void expectVec(const Vec3& actual, const Vec3& expected) {
    EXPECT_NEAR(actual.x(), expected.x(), kEps);
    EXPECT_NEAR(actual.y(), expected.y(), kEps);
    EXPECT_NEAR(actual.z(), expected.z(), kEps);
}

Pose streamPose(double x, double y, double z, double b, double c) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    p[Axis::B] = b;
    p[Axis::C] = c;
    return p;
}

TEST(WorkpieceFrame, MachinesWithoutTablesHaveNone) {
    EXPECT_FALSE(WorkpieceFrame::of(load("mill"), Pose{}).has_value());
}

// The golden case plane_spatial_turn_mill5 (its README, by hand): origin 50 mm above the pivot,
// B+45: the tilted-plane point (20, 0, -2) stands at the axes (-15.355339, 0, -16.644661); on the
// part it is Ry(45) (20, 0, -2) = (12.727922, 0, -15.556349), the tool along (sin 45, 0, cos 45).
TEST(WorkpieceFrame, MapsTheStreamBackOntoTheTurnedPart) {
    Pose preset;
    preset[Axis::Z] = -350.0;
    const auto frame = WorkpieceFrame::of(load("mill5"), preset);
    ASSERT_TRUE(frame.has_value());
    const ToolOnPart on = frame->toPart(streamPose(-15.355339, 0.0, -16.644661, 45.0, 0.0));
    expectVec(on.tip, {12.727922, 0.0, -15.556349});
    expectVec(on.axis, {std::sqrt(0.5), 0.0, std::sqrt(0.5)});
}

// C+90 turns the part by -90 about Z (the tool +90 relative to it): the machine point (10, 0)
// above the pivot is the part's (0, 10); B 0 keeps the tool along Z.
TEST(WorkpieceFrame, TurnsAboutTheRotaryTableAxis) {
    Pose preset;
    preset[Axis::Z] = -400.0;  // at the pivot
    const auto frame = WorkpieceFrame::of(load("mill5"), preset);
    ASSERT_TRUE(frame.has_value());
    const ToolOnPart on = frame->toPart(streamPose(10.0, 0.0, 5.0, 0.0, 90.0));
    expectVec(on.tip, {0.0, 10.0, 5.0});
    expectVec(on.axis, {0.0, 0.0, 1.0});
}

// A turn of 90 deg of C with the tool standing at X10 is an arc on the part, sampled every 10 deg:
// 9 points at radius 10, the last at the end.
TEST(WorkpieceFrame, SamplesASimultaneousMoveByTheTablesTurn) {
    Pose preset;
    preset[Axis::Z] = -400.0;
    const auto frame = WorkpieceFrame::of(load("mill5"), preset);
    ASSERT_TRUE(frame.has_value());
    std::vector<ToolOnPart> points;
    frame->sample(streamPose(10.0, 0.0, 0.0, 0.0, 0.0), streamPose(10.0, 0.0, 0.0, 0.0, 90.0), 10.0,
                  points);
    ASSERT_EQ(points.size(), 9u);
    for (const ToolOnPart& p : points)
        EXPECT_NEAR(p.tip.head<2>().norm(), 10.0, kEps);
    expectVec(points[0].tip,
              {10.0 * std::cos(0.17453292519943295), 10.0 * std::sin(0.17453292519943295), 0.0});
    expectVec(points.back().tip, {0.0, 10.0, 0.0});
    points.clear();
    frame->sample(streamPose(0.0, 0.0, 0.0, 0.0, 0.0), streamPose(5.0, 0.0, 0.0, 0.0, 0.0), 10.0,
                  points);
    EXPECT_EQ(points.size(), 1u);
}

}  // namespace
}  // namespace kerf::machine
