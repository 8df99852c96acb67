#include "core/cycles/cylinder/cylinder_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace kerf::cycles::cylinder {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr int kMaxChordsPerArc = 4096;

Vec2 nearestOnSegment(const PlanarSegment& s, const Vec2& p) {
    if (s.kind == PlanarSegment::Kind::Line) {
        const Vec2 d = s.end - s.start;
        const double length2 = d.squaredNorm();
        if (length2 < 1e-24) return s.start;
        return s.start + std::clamp((p - s.start).dot(d) / length2, 0.0, 1.0) * d;
    }
    // On the arc when the direction from the centre lies within the sweep, else an end.
    const Vec2 r = p - s.center;
    if (r.norm() > 1e-12) {
        const Vec2 a = s.start - s.center;
        const double at = std::atan2(a.x() * r.y() - a.y() * r.x(), a.dot(r));
        double along = s.sweep >= 0.0 ? at : -at;
        if (along < 0.0) along += 2.0 * std::numbers::pi;
        if (along <= std::fabs(s.sweep)) return s.center + r.normalized() * s.radius();
    }
    return (p - s.start).norm() <= (p - s.end).norm() ? s.start : s.end;
}

}  // namespace

ContourTrain unrolledInMm(const ContourTrain& train, double radiusMm, bool degrees,
                          double toleranceMm) {
    if (!degrees) return train;
    const double mmPerDeg = radiusMm / kDegPerRad;
    auto scaled = [mmPerDeg](const Vec2& p) { return Vec2(p.x() * mmPerDeg, p.y()); };
    ContourTrain out = train;
    out.segments.clear();
    for (const PlanarSegment& s : train.segments) {
        if (s.kind == PlanarSegment::Kind::Line) {
            out.segments.push_back(PlanarSegment::line(scaled(s.start), scaled(s.end)));
            continue;
        }
        // Chords whose sagitta, stretched by the scale, stays within the tolerance.
        const double stretch = std::max(mmPerDeg, 1.0) * s.radius();
        const double step = 2.0 * std::acos(std::max(0.0, 1.0 - toleranceMm / stretch));
        const int pieces =
            std::clamp(static_cast<int>(std::ceil(std::fabs(s.sweep) / std::max(step, 1e-6))), 1,
                       kMaxChordsPerArc);
        Vec2 from = s.start;
        const Vec2 r0 = s.start - s.center;
        for (int i = 1; i <= pieces; ++i) {
            const double a = s.sweep * i / pieces;
            const Vec2 to = i == pieces
                                ? s.end
                                : s.center + Vec2(std::cos(a) * r0.x() - std::sin(a) * r0.y(),
                                                  std::sin(a) * r0.x() + std::cos(a) * r0.y());
            out.segments.push_back(PlanarSegment::line(scaled(from), scaled(to)));
            from = to;
        }
    }
    return out;
}

Vec2 nearestOnChain(const Chain& chain, const Vec2& p) {
    Vec2 best = p;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const PlanarSegment& s : chain) {
        const Vec2 q = nearestOnSegment(s, p);
        const double d = (q - p).squaredNorm();
        if (d < bestDistance - 1e-18) {
            bestDistance = d;
            best = q;
        }
    }
    return best;
}

CylinderPose placeOnCylinder(const CylinderPlacement& placement, const Vec3& local,
                             const Chain* aligned) {
    double turnedMm = local.x();
    double sidewaysMm = 0.0;
    if (aligned != nullptr && !aligned->empty()) {
        turnedMm = nearestOnChain(*aligned, {local.x(), local.y()}).x();
        sidewaysMm = local.x() - turnedMm;
    }
    CylinderPose pose;
    pose.angleDeg = turnedMm / placement.radiusMm * kDegPerRad;
    pose.linear = placement.origin + local.y() * placement.axis +
                  sidewaysMm * placement.circumference() +
                  (placement.radiusMm + local.z()) * placement.tool;
    return pose;
}

}  // namespace kerf::cycles::cylinder
