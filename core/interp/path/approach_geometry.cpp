#include "core/interp/path/approach_geometry.h"

#include <cmath>

namespace kerf::interp {

namespace {

Vec2 rotate(const Vec2& v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// Direction of travel around `center` that moves along `tangent` at `point`: +1 CCW, -1 CW.
double travelSense(const Vec2& center, const Vec2& point, const Vec2& tangent) {
    return cross2(point - center, tangent) >= 0.0 ? 1.0 : -1.0;
}

// Centre and tool-centre radius of the TNC approach/departure arc of programmed radius `radius`
// touching the contour at `contourPoint`; `toolSide` is the unit normal towards the tool.
struct ToolCircle {
    Vec2 center;
    double radius;
};
std::optional<ToolCircle> toolCircle(const Vec2& contourPoint, const Vec2& toolSide, double reach,
                                     double radius) {
    if (std::fabs(radius) < 1e-9) return std::nullopt;
    ToolCircle c;
    c.center = contourPoint + radius * toolSide;
    c.radius = radius > 0.0 ? radius - reach : -radius + reach;
    if (c.radius <= 1e-9) return std::nullopt;
    return c;
}

// Tangent point on a circle for a line through `outside`, such that travel along the circle in
// direction `sense` continues the line (approach) or is continued by it (departure).
std::optional<Vec2> tangentPoint(const ToolCircle& circle, const Vec2& outside, double sense,
                                 bool lineFirst) {
    const Vec2 toPoint = outside - circle.center;
    const double distance = toPoint.norm();
    if (distance <= circle.radius + 1e-9) return std::nullopt;
    const double beta = std::acos(circle.radius / distance);
    const Vec2 base = toPoint / distance;
    for (double s : {1.0, -1.0}) {
        Vec2 t = circle.center + circle.radius * rotate(base, s * beta);
        Vec2 circleDir = sense * leftNormal((t - circle.center) / circle.radius);
        Vec2 lineDir = lineFirst ? Vec2(t - outside) : Vec2(outside - t);
        if (lineDir.dot(circleDir) > 0.0) return t;
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::vector<PlanarMove>> approachMoves(ApproachKind kind, const Vec2& start,
                                                     const Vec2& contourPoint, const Vec2& tangent,
                                                     double offset, double length, double angleDeg,
                                                     double radius) {
    const Vec2 toolSide = leftNormal(tangent) * (offset >= 0.0 ? 1.0 : -1.0);
    const double reach = std::fabs(offset);
    const Vec2 contourStart = contourPoint + reach * toolSide;
    std::vector<PlanarMove> moves;
    switch (kind) {
        case ApproachKind::Tangent: {
            Vec2 helper = contourPoint - length * tangent + reach * toolSide;
            moves.push_back({helper});
            moves.push_back({contourStart});
            return moves;
        }
        case ApproachKind::Normal: {
            Vec2 helper = contourPoint + (length + reach) * toolSide;
            moves.push_back({helper});
            moves.push_back({contourStart});
            return moves;
        }
        case ApproachKind::Circle: {
            auto circle = toolCircle(contourPoint, toolSide, reach, radius);
            if (!circle) return std::nullopt;
            double sense = travelSense(circle->center, contourStart, tangent);
            double sweep = sense * degToRad(std::fabs(angleDeg));
            Vec2 helper = circle->center + rotate(contourStart - circle->center, -sweep);
            moves.push_back({helper});
            moves.push_back({contourStart, true, circle->center, sweep});
            return moves;
        }
        case ApproachKind::LineCircle: {
            auto circle = toolCircle(contourPoint, toolSide, reach, std::fabs(radius));
            if (!circle) return std::nullopt;
            double sense = travelSense(circle->center, contourStart, tangent);
            auto touch = tangentPoint(*circle, start, sense, true);
            if (!touch) return std::nullopt;
            moves.push_back({*touch});
            double sweep = arcSweep(*touch, contourStart, circle->center, sense > 0.0);
            moves.push_back({contourStart, true, circle->center, sweep});
            return moves;
        }
    }
    return std::nullopt;
}

std::optional<std::vector<PlanarMove>> departureMoves(ApproachKind kind, const Vec2& contourPoint,
                                                      const Vec2& tangent, double offset,
                                                      double length, double angleDeg, double radius,
                                                      const Vec2& endPoint) {
    const Vec2 toolSide = leftNormal(tangent) * (offset >= 0.0 ? 1.0 : -1.0);
    const double reach = std::fabs(offset);
    const Vec2 contourEnd = contourPoint + reach * toolSide;
    std::vector<PlanarMove> moves;
    switch (kind) {
        case ApproachKind::Tangent:
            moves.push_back({contourEnd + length * tangent});
            return moves;
        case ApproachKind::Normal:
            moves.push_back({contourPoint + (length + reach) * toolSide});
            return moves;
        case ApproachKind::Circle: {
            auto circle = toolCircle(contourPoint, toolSide, reach, radius);
            if (!circle) return std::nullopt;
            double sense = travelSense(circle->center, contourEnd, tangent);
            double sweep = sense * degToRad(std::fabs(angleDeg));
            Vec2 end = circle->center + rotate(contourEnd - circle->center, sweep);
            moves.push_back({end, true, circle->center, sweep});
            return moves;
        }
        case ApproachKind::LineCircle: {
            auto circle = toolCircle(contourPoint, toolSide, reach, std::fabs(radius));
            if (!circle) return std::nullopt;
            double sense = travelSense(circle->center, contourEnd, tangent);
            auto touch = tangentPoint(*circle, endPoint, sense, false);
            if (!touch) return std::nullopt;
            double sweep = arcSweep(contourEnd, *touch, circle->center, sense > 0.0);
            moves.push_back({*touch, true, circle->center, sweep});
            moves.push_back({endPoint});
            return moves;
        }
    }
    return std::nullopt;
}

}  // namespace kerf::interp
