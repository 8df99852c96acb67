#include "graphics/toolpath/arc_tessellation.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::graphics {

bool finiteXyz(const Pose& pose) {
    return std::isfinite(pose.values[0]) && std::isfinite(pose.values[1]) &&
           std::isfinite(pose.values[2]);
}

int arcChordCount(double radiusMm, double sweepRad, double chordToleranceMm, int maxPoints) {
    const double sweep = std::fabs(sweepRad);
    if (!(radiusMm > 0.0) || !(sweep > 0.0) || !std::isfinite(radiusMm) || !std::isfinite(sweep)) {
        return 1;
    }
    const double tolerance = std::max(chordToleranceMm, 1e-9);
    // Sagitta of a chord spanning the angle a: r (1 - cos(a/2)) <= tolerance.
    double step = tolerance >= radiusMm ? kPi : 2.0 * std::acos(1.0 - tolerance / radiusMm);
    step = std::clamp(step, 1e-6, kPi / 2.0);  // at least 4 chords per turn
    const double count = std::ceil(sweep / step);
    return static_cast<int>(std::clamp(count, 1.0, static_cast<double>(std::max(1, maxPoints))));
}

void tessellateArc(const Pose& start, const canon::ArcMove& arc, double chordToleranceMm,
                   int maxPoints, std::vector<Vec3>& out) {
    const Vec3 end = arc.target.xyz();
    const PlaneAxes axes = planeAxes(arc.plane);
    const int i0 = axisIndex(axes.first);
    const int i1 = axisIndex(axes.second);
    const int in = axisIndex(axes.normal);
    const Vec3 from = start.xyz();
    const double cx = arc.center[i0];
    const double cy = arc.center[i1];
    const double dx = from[i0] - cx;
    const double dy = from[i1] - cy;
    const double radius = std::hypot(dx, dy);
    const int count = arcChordCount(radius, arc.sweepRad, chordToleranceMm, maxPoints);
    if (count <= 1 || !std::isfinite(cx) || !std::isfinite(cy)) {
        out.push_back(end);
        return;
    }
    const double a0 = std::atan2(dy, dx);
    const double normal0 = from[in];
    const double normal1 = end[in];
    for (int k = 1; k < count; ++k) {
        const double t = static_cast<double>(k) / count;
        const double a = a0 + arc.sweepRad * t;
        Vec3 p;
        p[i0] = cx + radius * std::cos(a);
        p[i1] = cy + radius * std::sin(a);
        p[in] = normal0 + (normal1 - normal0) * t;
        out.push_back(p);
    }
    // The programmed target closes the arc exactly, whatever rounding the centre carried.
    out.push_back(end);
}

}  // namespace kerf::graphics
