// The simulated TT: where a flat tool (a cylinder) first touches a disc or cube stylus.
#include "core/workpiece/simulated_tool_probe.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf::workpiece {
namespace {

// A disc of diameter 40 whose top is at machine (-200, 50, -300); a tool 100 long, radius 5.
const ToolProbeStylus kDisc{Vec3(-200.0, 50.0, -300.0), 40.0, false};
const RealTool kTool{100.0, 5.0};

TEST(SimulatedToolProbe, EndFaceTouchesTheTopAtTheToolLengthAbove) {
    const SimulatedToolProbe tt(kDisc);
    // Gauge point 110 above the top with the axis 5 off the centre: the end face reaches the
    // top after 10.
    auto hit = tt.touch(Vec3(-195.0, 50.0, -190.0), Vec3(0.0, 0.0, -1.0), 20.0, kTool);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z(), -200.0, 1e-9);
    EXPECT_NEAR(hit->x(), -195.0, 1e-12);
    // Beside the disc (axis 25.1 from the centre, the tool's edge 0.1 clear): no touch.
    EXPECT_FALSE(tt.touch(Vec3(-174.9, 50.0, -190.0), Vec3(0.0, 0.0, -1.0), 20.0, kTool));
    // Too short a path.
    EXPECT_FALSE(tt.touch(Vec3(-195.0, 50.0, -190.0), Vec3(0.0, 0.0, -1.0), 9.9, kTool));
}

TEST(SimulatedToolProbe, SideTouchesTheRimAtBothRadii) {
    const SimulatedToolProbe tt(kDisc);
    // End face 2 below the top (-302); from the -X side along +X the axis stops 20 + 5 from the
    // centre.
    auto hit = tt.touch(Vec3(-240.0, 50.0, -302.0 + 100.0), Vec3(1.0, 0.0, 0.0), 30.0, kTool);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), -225.0, 1e-9);
    // Off the centre line by 15: the axis stops where it is 25 from the centre.
    hit = tt.touch(Vec3(-240.0, 65.0, -302.0 + 100.0), Vec3(1.0, 0.0, 0.0), 30.0, kTool);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), -200.0 - std::sqrt(25.0 * 25.0 - 15.0 * 15.0), 1e-7);
    // Above the top the tool passes over it.
    EXPECT_FALSE(tt.touch(Vec3(-240.0, 50.0, -299.0 + 100.0), Vec3(1.0, 0.0, 0.0), 80.0, kTool));
}

TEST(SimulatedToolProbe, CubeStylusHasFlatSides) {
    const SimulatedToolProbe tt({Vec3(-200.0, 50.0, -300.0), 40.0, true});
    // Off the centre line by 15, a cube's side still stops the axis 20 + 5 from the centre.
    auto hit = tt.touch(Vec3(-240.0, 65.0, -302.0 + 100.0), Vec3(1.0, 0.0, 0.0), 30.0, kTool);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->x(), -225.0, 1e-9);
}

TEST(SimulatedToolProbe, DeflectedWhenTheToolAlreadyOverlaps) {
    const SimulatedToolProbe tt(kDisc);
    EXPECT_TRUE(tt.touches(Vec3(-200.0, 50.0, -200.5), kTool));
    EXPECT_FALSE(tt.touches(Vec3(-200.0, 50.0, -199.5), kTool));
    EXPECT_TRUE(tt.touches(Vec3(-224.5, 50.0, -210.0), kTool));
}

}  // namespace
}  // namespace kerf::workpiece
