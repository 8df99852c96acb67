// Where LN puts the tip of a cutter that differs from the CAM system's, each value from the
// cutter drawn by hand: nominal tip at the origin, the contact point C where the nominal cutter
// touches the surface, then the actual cutter placed on C with the same normal.
#include "core/interp/klartext/cutter_oversize.h"

#include <gtest/gtest.h>

namespace kerf::klartext {
namespace {

void expectNear(const Vec3& got, const Vec3& want) {
    EXPECT_NEAR(got.x(), want.x(), 1e-12);
    EXPECT_NEAR(got.y(), want.y(), 1e-12);
    EXPECT_NEAR(got.z(), want.z(), 1e-12);
}

const Vec3 kUp(0.0, 0.0, 1.0);

// Ball R 5 on a slope with normal (0.6, 0, 0.8): centre (0, 0, 5), C = centre - 5n = (-3, 0, 1).
// A ball of 4.8: centre C + 4.8n = (-0.12, 0, 4.84), tip 4.8 below it: (-0.12, 0, 0.04).
TEST(CutterOversize, BallCutterTouchesWithItsSphere) {
    expectNear(cutterOversizeOffset(Vec3(0.6, 0.0, 0.8), kUp, -0.2, -0.2), Vec3(-0.12, 0.0, 0.04));
}

// End mill R 5 on the same slope touches with its rim at (-5, 0, 0); a rim of 4.5 there puts the
// tip at (-0.5, 0, 0): across the tool, not along the normal. On a flat floor the face touches.
TEST(CutterOversize, EndMillTouchesWithItsRim) {
    expectNear(cutterOversizeOffset(Vec3(0.6, 0.0, 0.8), kUp, -0.5, 0.0), Vec3(-0.5, 0.0, 0.0));
    expectNear(cutterOversizeOffset(kUp, kUp, -0.5, 0.0), Vec3::Zero());
}

// Toroid R 5, R2 2, normal (0, 0.6, 0.8): corner centre (0, -3, 2), C = (0, -4.2, 0.4). R 4.7,
// R2 1.9: corner centre C + 1.9n = (0, -3.06, 1.92), the axis 2.8 across it at y -0.26, the tip
// 1.9 below: (0, -0.26, 0.02).
TEST(CutterOversize, ToroidCutterTouchesWithItsCorner) {
    expectNear(cutterOversizeOffset(Vec3(0.0, 0.6, 0.8), kUp, -0.3, -0.1), Vec3(0.0, -0.26, 0.02));
}

// Ball R 5 tilted along (0.6, 0, 0.8) on a flat floor: centre (3, 0, 4), C = (3, 0, -1). A ball
// of 4.5: centre (3, 0, 3.5), tip 4.5 back along the tool: (0.3, 0, -0.1). Along the normal the
// pole touches whatever the radius.
TEST(CutterOversize, TiltedBallCutter) {
    expectNear(cutterOversizeOffset(kUp, Vec3(0.6, 0.0, 0.8), -0.5, -0.5), Vec3(0.3, 0.0, -0.1));
    expectNear(cutterOversizeOffset(Vec3(0.6, 0.0, 0.8), Vec3(0.6, 0.0, 0.8), -0.5, -0.5),
               Vec3::Zero());
}

}  // namespace
}  // namespace kerf::klartext
