#include "core/cycles/probing/manual_probing.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

#include "core/cycles/probing/probe_geometry.h"

namespace kerf::cycles::probing {

namespace {

Vec3 surfacePoint(const ManualTouch& touch, double ballRadius) {
    return touch.ball + ballRadius * touch.direction;
}

// The misalignment of the edge through a and b that was probed by `touch`: its angle to the
// axis square to the operator's probing axis, folded to (-90, 90] (which point came first does
// not count).
std::optional<double> edgeRotation(const Vec2& a, const Vec2& b, const ManualTouch& touch) {
    if (!lineAngleDeg(a, b)) return std::nullopt;
    const Vec3& direction = touch.direction;
    const double probing = std::atan2(direction.y(), direction.x()) * 180.0 / std::numbers::pi -
                           touch.basicRotationDeg;
    double angle = normalizedDeg(*lineAngleDeg(a, b) - probing - 90.0);
    if (angle > 90.0) angle -= 180.0;
    if (angle <= -90.0) angle += 180.0;
    return angle;
}

// A point of the untilted workpiece axes in the system turned by the basic rotation (about
// the origin), where the position display shows it.
Vec3 inTurnedSystem(const Vec3& point, double basicRotationDeg) {
    return turnedProbingDirection(point, -basicRotationDeg);
}

}  // namespace

Vec3 turnedProbingDirection(const Vec3& axisDirection, double basicRotationDeg) {
    const double a = basicRotationDeg * std::numbers::pi / 180.0;
    return {std::cos(a) * axisDirection.x() - std::sin(a) * axisDirection.y(),
            std::sin(a) * axisDirection.x() + std::cos(a) * axisDirection.y(), axisDirection.z()};
}

int manualTouchCount(ManualProbingFunction function) {
    switch (function) {
        case ManualProbingFunction::Rotation:
            return 2;
        case ManualProbingFunction::Position:
            return 1;
        case ManualProbingFunction::Corner:
        case ManualProbingFunction::Circle:
            return 4;
        case ManualProbingFunction::Plane:
            return 3;
    }
    return 1;
}

std::optional<ManualProbingResult> evaluateManualProbing(ManualProbingFunction function,
                                                         std::span<const ManualTouch> touches,
                                                         double ballRadius) {
    if (static_cast<int>(touches.size()) != manualTouchCount(function)) return std::nullopt;
    std::vector<Vec3> surface;
    for (const ManualTouch& touch : touches)
        surface.push_back(surfacePoint(touch, ballRadius));
    ManualProbingResult result;
    switch (function) {
        case ManualProbingFunction::Position: {
            // The axis the operator chose.
            const Vec3 chosen =
                turnedProbingDirection(touches[0].direction, -touches[0].basicRotationDeg);
            int axis = 0;
            for (int i = 1; i < 3; ++i)
                if (std::fabs(chosen[i]) > std::fabs(chosen[axis])) axis = i;
            result.point[static_cast<size_t>(axis)] =
                inTurnedSystem(surface[0], touches[0].basicRotationDeg)[axis];
            return result;
        }
        case ManualProbingFunction::Rotation:
            result.basicRotationDeg =
                edgeRotation(surface[0].head<2>(), surface[1].head<2>(), touches[0]);
            if (!result.basicRotationDeg) return std::nullopt;
            return result;
        case ManualProbingFunction::Corner: {
            const auto corner = intersect(surface[0].head<2>(), surface[1].head<2>(),
                                          surface[2].head<2>(), surface[3].head<2>());
            result.basicRotationDeg =
                edgeRotation(surface[0].head<2>(), surface[1].head<2>(), touches[0]);
            if (!corner || !result.basicRotationDeg) return std::nullopt;
            const Vec3 shown =
                inTurnedSystem(Vec3(corner->x(), corner->y(), 0.0), touches[0].basicRotationDeg);
            result.point[0] = shown.x();
            result.point[1] = shown.y();
            return result;
        }
        case ManualProbingFunction::Circle: {
            // The ball centres lie on a circle about the real centre whatever the directions.
            std::vector<Vec2> balls;
            for (const ManualTouch& touch : touches)
                balls.push_back(touch.ball.head<2>());
            const auto circle = fitCircle(balls);
            if (!circle) return std::nullopt;
            // Touches away from the centre found a hole's wall, towards it a stud's.
            const Vec2 outward = balls[0] - circle->centre;
            const bool hole = outward.dot(touches[0].direction.head<2>()) > 0.0;
            const Vec3 shown = inTurnedSystem(Vec3(circle->centre.x(), circle->centre.y(), 0.0),
                                              touches[0].basicRotationDeg);
            result.point[0] = shown.x();
            result.point[1] = shown.y();
            result.diameter =
                2.0 * (hole ? circle->radius + ballRadius : circle->radius - ballRadius);
            return result;
        }
        case ManualProbingFunction::Plane: {
            // The ball centres lie on the face moved along its normal: the same slopes.
            const Vec3 normal =
                (touches[1].ball - touches[0].ball).cross(touches[2].ball - touches[0].ball);
            if (normal.norm() < 1e-9 || std::fabs(normal.z()) < 1e-9) return std::nullopt;
            const double a = -normal.x() / normal.z();
            const double b = -normal.y() / normal.z();
            constexpr double kDeg = 180.0 / std::numbers::pi;
            result.planeADeg = std::atan2(b, std::sqrt(1.0 + a * a)) * kDeg;
            result.planeBDeg = -std::atan(a) * kDeg;
            return result;
        }
    }
    return std::nullopt;
}

}  // namespace kerf::cycles::probing
