#include "core/workpiece/tool_sweep.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kerf::workpiece {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The core cylinder's height range above the tip (its dilation by the corner radius gives the
// cutter: bottom at the tip, top at the tip + length).
double coreLow(const Cutter& c) {
    return c.cornerRadius;
}
double coreHigh(const Cutter& c) {
    return std::max(c.length - c.cornerRadius, c.cornerRadius);
}
double coreRadius(const Cutter& c) {
    return c.radius - c.cornerRadius;
}

double height(const Cutter& c) {
    return coreHigh(c) + c.cornerRadius;
}

// A plane region (signed distance `planar`) extruded from zLow to zHigh.
double extruded(double planar, double zLow, double zHigh, double z) {
    const Vec2 q(planar, std::max(zLow - z, z - zHigh));
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double length2 = d.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + t * d)).norm();
}

double arcDistance(const ArcSweep& arc, const Vec2& p) {
    const Vec2 v = p - arc.centre;
    const double rho = v.norm();
    if (std::abs(arc.sweepRad) >= kTwoPi || rho == 0.0) return std::abs(rho - arc.radius);
    // The angle from the start, counted in the sweep's sense, in [0, 2 pi).
    double phi = std::atan2(v.y(), v.x()) - arc.startRad;
    if (arc.sweepRad < 0.0) phi = -phi;
    phi = std::fmod(phi, kTwoPi);
    if (phi < 0.0) phi += kTwoPi;
    if (phi <= std::abs(arc.sweepRad)) return std::abs(rho - arc.radius);
    const double end = arc.startRad + arc.sweepRad;
    const Vec2 first =
        arc.centre + arc.radius * Vec2(std::cos(arc.startRad), std::sin(arc.startRad));
    const Vec2 last = arc.centre + arc.radius * Vec2(std::cos(end), std::sin(end));
    return std::min((p - first).norm(), (p - last).norm());
}

// The core cylinder with its tip at `tip`.
double coreDistance(const Cutter& c, const Vec3& tip, const Vec3& p) {
    const double planar = Vec2(p.x() - tip.x(), p.y() - tip.y()).norm() - coreRadius(c);
    return extruded(planar, tip.z() + coreLow(c), tip.z() + coreHigh(c), p.z());
}

// The core swept along a line: the union of its translates, so the distance is the least over
// the line's points, a convex function of the parameter (the distance to a convex body along a
// straight line); golden-section search finds it to far below a nanometre.
double lineCoreDistance(const Cutter& c, const LineSweep& line, const Vec3& p) {
    const Vec3 d = line.to - line.from;
    const Vec2 planarStep(d.x(), d.y());
    if (d.z() == 0.0) {  // in the plane: a stadium, extruded
        const double planar =
            segmentDistance(Vec2(p.x(), p.y()), Vec2(line.from.x(), line.from.y()),
                            Vec2(line.to.x(), line.to.y())) -
            coreRadius(c);
        return extruded(planar, line.from.z() + coreLow(c), line.from.z() + coreHigh(c), p.z());
    }
    if (planarStep.squaredNorm() == 0.0) {  // along the axis: a longer cylinder
        const double planar =
            Vec2(p.x() - line.from.x(), p.y() - line.from.y()).norm() - coreRadius(c);
        const double low = std::min(line.from.z(), line.to.z());
        const double high = std::max(line.from.z(), line.to.z());
        return extruded(planar, low + coreLow(c), high + coreHigh(c), p.z());
    }
    auto at = [&](double t) { return coreDistance(c, line.from + t * d, p); };
    constexpr double kRatio = 0.6180339887498949;
    double a = 0.0;
    double b = 1.0;
    double x1 = b - kRatio * (b - a);
    double x2 = a + kRatio * (b - a);
    double f1 = at(x1);
    double f2 = at(x2);
    for (int i = 0; i < 60; ++i) {
        if (f1 <= f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - kRatio * (b - a);
            f1 = at(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + kRatio * (b - a);
            f2 = at(x2);
        }
    }
    return std::min({f1, f2, at(0.0), at(1.0)});
}

}  // namespace

Sweep sweepAlongLine(const Cutter& cutter, const Vec3& from, const Vec3& to) {
    Sweep sweep{LineSweep{from, to}, cutter, {}, {}};
    const Vec3 reach(cutter.radius, cutter.radius, 0.0);
    sweep.boxMin = from.cwiseMin(to) - reach;
    sweep.boxMax = from.cwiseMax(to) + reach + Vec3(0.0, 0.0, height(cutter));
    return sweep;
}

Sweep sweepAlongArc(const Cutter& cutter, const ArcSweep& arc) {
    Sweep sweep{arc, cutter, {}, {}};
    const double reach = arc.radius + cutter.radius;
    sweep.boxMin = Vec3(arc.centre.x() - reach, arc.centre.y() - reach, arc.z);
    sweep.boxMax = Vec3(arc.centre.x() + reach, arc.centre.y() + reach, arc.z + height(cutter));
    return sweep;
}

double sweepDistance(const Sweep& sweep, const Vec3& p) {
    const Cutter& c = sweep.cutter;
    double core = 0.0;
    if (const auto* line = std::get_if<LineSweep>(&sweep.path)) {
        core = lineCoreDistance(c, *line, p);
    } else {
        const auto& arc = std::get<ArcSweep>(sweep.path);
        const Vec2 q(p.x(), p.y());
        // A full circle no wider than the cutter clears a disc: its depth is exact then.
        const bool disc = std::abs(arc.sweepRad) >= kTwoPi && coreRadius(c) >= arc.radius;
        const double planar = disc ? (q - arc.centre).norm() - (arc.radius + coreRadius(c))
                                   : arcDistance(arc, q) - coreRadius(c);
        core = extruded(planar, arc.z + coreLow(c), arc.z + coreHigh(c), p.z());
    }
    return core - c.cornerRadius;
}

}  // namespace kerf::workpiece
