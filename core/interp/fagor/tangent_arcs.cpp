#include "core/interp/fagor/tangent_arcs.h"

#include <array>
#include <cmath>

namespace kerf::fagor {

namespace {

constexpr double kEps = 1e-9;

struct Candidate {
    Vec2 center;
    bool ccw;
};

// The two circles of `radius` tangent to the direction `tangent` at `point`, each with the sense
// in which it is travelled along that direction.
std::array<Candidate, 2> circlesAt(const Vec2& point, const Vec2& tangent, double radius) {
    const Vec2 n = leftNormal(tangent);
    return {{{point + radius * n, true}, {point - radius * n, false}}};
}

// The point where a line through `outside` touches the circle, such that the circle's travel
// direction there points along the line away from (`leaving`) or towards `outside`.
std::optional<Vec2> touchPoint(const Candidate& c, double radius, const Vec2& outside,
                               bool leaving) {
    const Vec2 d = outside - c.center;
    const double distance = d.norm();
    if (distance <= radius * (1.0 + 1e-12)) return std::nullopt;
    const double base = std::atan2(d.y(), d.x());
    const double alpha = std::acos(radius / distance);
    for (double a : {base + alpha, base - alpha}) {
        const Vec2 t = c.center + radius * Vec2(std::cos(a), std::sin(a));
        Vec2 travel = leftNormal((t - c.center) / radius);
        if (!c.ccw) travel = -travel;
        const Vec2 line = leaving ? Vec2(outside - t) : Vec2(t - outside);
        if (line.dot(travel) > 0.0) return t;
    }
    return std::nullopt;
}

double sweepBetween(const Vec2& from, const Vec2& to, const Vec2& center, bool ccw) {
    if ((to - from).norm() < kEps) return 0.0;
    return arcSweep(from, to, center, ccw);
}

}  // namespace

std::optional<TangentArc> tangentialEntry(const Vec2& start, const Vec2& contourPoint,
                                          const Vec2& tangent, double radius) {
    if (radius <= kEps) return std::nullopt;
    std::optional<TangentArc> best;
    for (const Candidate& c : circlesAt(contourPoint, tangent, radius)) {
        auto t = touchPoint(c, radius, start, false);
        if (!t) continue;
        TangentArc arc{*t, c.center, sweepBetween(*t, contourPoint, c.center, c.ccw)};
        if (!best || std::fabs(arc.sweep) < std::fabs(best->sweep)) best = arc;
    }
    return best;
}

std::optional<TangentArc> tangentialExit(const Vec2& contourPoint, const Vec2& tangent,
                                         const Vec2& end, double radius) {
    if (radius <= kEps) return std::nullopt;
    std::optional<TangentArc> best;
    for (const Candidate& c : circlesAt(contourPoint, tangent, radius)) {
        auto t = touchPoint(c, radius, end, true);
        if (!t) continue;
        TangentArc arc{*t, c.center, sweepBetween(contourPoint, *t, c.center, c.ccw)};
        if (!best || std::fabs(arc.sweep) < std::fabs(best->sweep)) best = arc;
    }
    return best;
}

}  // namespace kerf::fagor
