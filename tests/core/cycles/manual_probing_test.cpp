// Manual operation's probing functions evaluated from touches whose ball centres are placed by
// hand on known features.
#include "core/cycles/probing/manual_probing.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace kerf::cycles::probing {
namespace {

constexpr double kBall = 2.0;

TEST(ManualProbing, CircleCentreAndDiameterOfAHoleFromAnyFourDirections) {
    // A hole of diameter 30 about (12, -7): the ball centres lie on radius 15 - r_b = 13, each
    // touch going outward (not along the axes: the fit does not care).
    const Vec2 centre(12.0, -7.0);
    std::vector<ManualTouch> touches;
    for (double deg : {10.0, 100.0, 200.0, 300.0}) {
        const double a = deg * std::numbers::pi / 180.0;
        const Vec3 out(std::cos(a), std::sin(a), 0.0);
        touches.push_back({Vec3(centre.x(), centre.y(), -5.0) + 13.0 * out, out});
    }
    const auto result = evaluateManualProbing(ManualProbingFunction::Circle, touches, kBall);
    ASSERT_TRUE(result);
    EXPECT_NEAR(*result->point[0], 12.0, 1e-9);
    EXPECT_NEAR(*result->point[1], -7.0, 1e-9);
    EXPECT_FALSE(result->point[2]);
    EXPECT_NEAR(*result->diameter, 30.0, 1e-9);
}

TEST(ManualProbing, CircleOfAStudIsProbedInwards) {
    // A stud of diameter 40 about the origin: ball centres on 20 + r_b = 22, touches inward.
    std::vector<ManualTouch> touches;
    for (double deg : {0.0, 90.0, 180.0, 270.0}) {
        const double a = deg * std::numbers::pi / 180.0;
        const Vec3 out(std::cos(a), std::sin(a), 0.0);
        touches.push_back({22.0 * out, -out});
    }
    const auto result = evaluateManualProbing(ManualProbingFunction::Circle, touches, kBall);
    ASSERT_TRUE(result);
    EXPECT_NEAR(*result->diameter, 40.0, 1e-9);
}

TEST(ManualProbing, RotationIsTheEdgesAngleWhicheverPointCameFirst) {
    // An edge along X turned by +3 degrees, probed along +Y: the misalignment is +3 with the
    // points in either order; an edge along Y probed along -X turned by -2 degrees gives -2.
    const double t = 3.0 * std::numbers::pi / 180.0;
    const Vec3 y(0.0, 1.0, 0.0);
    const ManualTouch a{Vec3(10.0, 10.0 * std::tan(t) - kBall, 0.0), y};
    const ManualTouch b{Vec3(70.0, 70.0 * std::tan(t) - kBall, 0.0), y};
    for (const auto& pair : {std::vector<ManualTouch>{a, b}, std::vector<ManualTouch>{b, a}}) {
        const auto r = evaluateManualProbing(ManualProbingFunction::Rotation, pair, kBall);
        ASSERT_TRUE(r);
        EXPECT_NEAR(*r->basicRotationDeg, 3.0, 1e-9);
    }
    const double u = -2.0 * std::numbers::pi / 180.0;
    const Vec3 minusX(-1.0, 0.0, 0.0);
    // The edge x = -y tan(u) (turned -2 degrees from +Y), the ball r_b on its +X side.
    const ManualTouch c{Vec3(-5.0 * std::tan(u) + kBall, 5.0, 0.0), minusX};
    const ManualTouch d{Vec3(-40.0 * std::tan(u) + kBall, 40.0, 0.0), minusX};
    const std::vector<ManualTouch> side{c, d};
    const auto r = evaluateManualProbing(ManualProbingFunction::Rotation, side, kBall);
    ASSERT_TRUE(r);
    EXPECT_NEAR(*r->basicRotationDeg, -2.0, 1e-9);
}

TEST(ManualProbing, UnderABasicRotationTheTouchesGoAlongTheTurnedAxes) {
    EXPECT_TRUE(
        turnedProbingDirection(Vec3(1.0, 0.0, 0.0), 90.0).isApprox(Vec3(0.0, 1.0, 0.0), 1e-12));
    EXPECT_TRUE(
        turnedProbingDirection(Vec3(0.0, 0.0, -1.0), 30.0).isApprox(Vec3(0.0, 0.0, -1.0), 1e-12));
    // An edge through the origin turned by 3 degrees, probed along +Y turned by the active basic
    // rotation b: each touch stops where the ball meets the face along that direction. The
    // result is the edge's whole misalignment, 3, not what is left after b.
    const double t = 3.0 * std::numbers::pi / 180.0;
    const Vec2 edge(std::cos(t), std::sin(t));
    const Vec2 normal(-std::sin(t), std::cos(t));  // into the material
    for (double b : {3.0, 1.0}) {
        const Vec3 d = turnedProbingDirection(Vec3(0.0, 1.0, 0.0), b);
        // Ball centre c = s edge - k d with c . normal = -r_b: k = r_b / (d . normal).
        const double k = kBall / d.head<2>().dot(normal);
        std::vector<ManualTouch> touches;
        for (double s : {10.0, 60.0}) {
            const Vec2 ball = s * edge - k * d.head<2>();
            touches.push_back({Vec3(ball.x(), ball.y(), -5.0), d, b});
        }
        const auto r = evaluateManualProbing(ManualProbingFunction::Rotation, touches, kBall);
        ASSERT_TRUE(r);
        EXPECT_NEAR(*r->basicRotationDeg, 3.0, 1e-9) << b;
    }
}

TEST(ManualProbing, UnderABasicRotationPointsAreInTheTurnedSystem) {
    // POS along X+ turned by b = 30 degrees from the ball at (10, 5): the surface point
    // (10, 5) + 2 (cos b, sin b) lies at x' = 10 cos b + 5 sin b + 2 along the turned X axis,
    // the coordinate the display shows there.
    const double b = 30.0 * std::numbers::pi / 180.0;
    const Vec3 d = turnedProbingDirection(Vec3(1.0, 0.0, 0.0), 30.0);
    const std::vector<ManualTouch> pos{{Vec3(10.0, 5.0, -5.0), d, 30.0}};
    const auto r = evaluateManualProbing(ManualProbingFunction::Position, pos, kBall);
    ASSERT_TRUE(r && r->point[0]);
    EXPECT_FALSE(r->point[1]);
    EXPECT_NEAR(*r->point[0], 10.0 * std::cos(b) + 5.0 * std::sin(b) + 2.0, 1e-12);
    // CC about (3, 4) under a basic rotation of 90 degrees: the turned X axis is the old Y,
    // the turned Y the old -X, so the centre shows at (4, -3).
    std::vector<ManualTouch> hole;
    for (int k = 0; k < 4; ++k) {
        const double a = k * std::numbers::pi / 2.0;
        const Vec3 out(std::cos(a), std::sin(a), 0.0);
        hole.push_back({Vec3(3.0, 4.0, -5.0) + 5.0 * out, out, 90.0});
    }
    const auto cc = evaluateManualProbing(ManualProbingFunction::Circle, hole, kBall);
    ASSERT_TRUE(cc);
    EXPECT_NEAR(*cc->point[0], 4.0, 1e-9);
    EXPECT_NEAR(*cc->point[1], -3.0, 1e-9);
    EXPECT_NEAR(*cc->diameter, 14.0, 1e-9);
}

TEST(ManualProbing, PositionGivesTheSurfaceInTheProbingAxisOnly) {
    const std::vector<ManualTouch> down{{Vec3(3.0, 4.0, 2.5), Vec3(0.0, 0.0, -1.0)}};
    const auto r = evaluateManualProbing(ManualProbingFunction::Position, down, kBall);
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->point[0]);
    EXPECT_FALSE(r->point[1]);
    EXPECT_NEAR(*r->point[2], 0.5, 1e-12);  // the ball's south pole
}

TEST(ManualProbing, ParallelEdgesOrMissingTouchesGiveNoResult) {
    const Vec3 y(0.0, 1.0, 0.0);
    const std::vector<ManualTouch> parallel{{Vec3(0.0, 0.0, 0.0), y},
                                            {Vec3(10.0, 0.0, 0.0), y},
                                            {Vec3(0.0, 5.0, 0.0), y},
                                            {Vec3(10.0, 5.0, 0.0), y}};
    EXPECT_FALSE(evaluateManualProbing(ManualProbingFunction::Corner, parallel, kBall));
    const std::vector<ManualTouch> one{{Vec3(0.0, 0.0, 0.0), y}};
    EXPECT_FALSE(evaluateManualProbing(ManualProbingFunction::Rotation, one, kBall));
}

TEST(ManualProbing, PlaneGivesTheSpatialAnglesThatTurnTheToolAxisOntoItsNormal) {
    // A face turned by R = Ry(-3 deg) Rx(5 deg): its normal is R e_z. Three points on it (any
    // two directions square to the normal), the ball centres r_b along the normal from them.
    const double a = 5.0 * std::numbers::pi / 180.0;
    const double b = -3.0 * std::numbers::pi / 180.0;
    const Eigen::Matrix3d rotation =
        (Eigen::AngleAxisd(b, Vec3::UnitY()) * Eigen::AngleAxisd(a, Vec3::UnitX()))
            .toRotationMatrix();
    const Vec3 normal = rotation * Vec3::UnitZ();
    const Vec3 u = rotation * Vec3::UnitX();
    const Vec3 v = rotation * Vec3::UnitY();
    const Vec3 origin(10.0, 20.0, -3.0);
    std::vector<ManualTouch> touches;
    for (const Vec3& p : {Vec3(origin), Vec3(origin + 40.0 * u), Vec3(origin + 25.0 * v - 5.0 * u)})
        touches.push_back({p + kBall * normal, Vec3(0.0, 0.0, -1.0)});
    const auto result = evaluateManualProbing(ManualProbingFunction::Plane, touches, kBall);
    ASSERT_TRUE(result);
    EXPECT_NEAR(*result->planeADeg, 5.0, 1e-9);
    EXPECT_NEAR(*result->planeBDeg, -3.0, 1e-9);
    // Three points on one line give no plane.
    touches[2].ball = touches[0].ball + 2.0 * (touches[1].ball - touches[0].ball);
    EXPECT_FALSE(evaluateManualProbing(ManualProbingFunction::Plane, touches, kBall));
}

}  // namespace
}  // namespace kerf::cycles::probing
