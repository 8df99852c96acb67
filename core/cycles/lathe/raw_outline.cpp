#include "core/cycles/lathe/raw_outline.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {

namespace {
constexpr int kMaxChordsPerArc = 4096;
}  // namespace

std::vector<Vec2> rawOutlinePoints(const RawStock& raw, double chordErrorMm) {
    std::vector<Vec2> points;
    if (raw.elements.empty()) return points;
    points.push_back(raw.start);
    for (const ProfileElement& e : raw.elements) {
        const Vec2 from = points.back();
        if (e.centre) {
            const Vec2 c = *e.centre;
            const double radius = (from - c).norm();
            const double sweep = arcSweep(from, e.end, c, e.ccw);
            // A chord of angle a lies r (1 - cos(a/2)) from the arc.
            const double tolerance = std::clamp(chordErrorMm, 1e-6, radius);
            const double maxAngle = 2.0 * std::acos(1.0 - tolerance / std::max(radius, 1e-9));
            const int steps =
                std::clamp(static_cast<int>(std::ceil(std::fabs(sweep) / std::max(maxAngle, 1e-9))),
                           1, kMaxChordsPerArc);
            const double a0 = std::atan2(from.y() - c.y(), from.x() - c.x());
            for (int i = 1; i < steps; ++i) {
                const double a = a0 + sweep * i / steps;
                points.emplace_back(c.x() + radius * std::cos(a), c.y() + radius * std::sin(a));
            }
        }
        points.push_back(e.end);
    }
    return points;
}

}  // namespace kerf::cycles::lathe
