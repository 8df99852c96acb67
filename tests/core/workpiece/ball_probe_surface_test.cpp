// The surface a Klartext probing cycle hands to the simulated machine: the ball on the placed part,
// its centre an affine map of the drives' tool tip.
#include "core/workpiece/ball_probe_surface.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace kerf::workpiece {
namespace {

TEST(BallProbeSurface, TheBallAboveTheTipTouchesTheTurnedAndShiftedBlock) {
    // A 100 x 60 x 40 block, top at Z 0, placed with shift (1.5, -0.8, -0.2) and 0.7 degrees; a
    // ball of radius 2 whose centre lies 2 above the tool tip.
    SimulatedWorkpiece part(Placement{{1.5, -0.8, -0.2}, 0.7, {0.0, 0.0, 0.0}});
    part.add(Solid{Box{{0.0, 0.0, -40.0}, {100.0, 60.0, 0.0}}, true});
    const BallProbeSurface surface(part, Eigen::Affine3d(Eigen::Translation3d(0.0, 0.0, 2.0)), 2.0);
    // Over the top at X 50, Y 30: the real top is at Z -0.2, the ball's south pole is the tip.
    EXPECT_FALSE(surface.touches({50.0, 30.0, -0.2 + 1e-6}));
    EXPECT_TRUE(surface.touches({50.0, 30.0, -0.2 - 1e-6}));
    // In front of the front face at X 40, the ball centre at Z -5: the face, turned by 0.7
    // degrees about the programmed origin and shifted, passes X 40 at faceY; on the line X 40 the
    // ball centre is 2 from the face 2 / cos 0.7deg before it.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double faceY = (40.0 - 1.5) * std::tan(a) - 0.8;  // the face's Y at X 40
    const double touchY = faceY - 2.0 / std::cos(a);        // ball centre 2 from the face
    EXPECT_FALSE(surface.touches({40.0, touchY - 1e-6, -7.0}));
    EXPECT_TRUE(surface.touches({40.0, touchY + 1e-6, -7.0}));
}

}  // namespace
}  // namespace kerf::workpiece
