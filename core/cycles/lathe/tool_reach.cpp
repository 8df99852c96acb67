// The tool/profile analysis (spec part 2 §1.6): which valleys the selected insert cannot reach.
#include "core/cycles/lathe/tool_reach.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kAngleToleranceDeg = 1e-6;
constexpr int kArcSamples = 64;

// The direction of the path at parameter s (0..1) of an element from `from`.
Vec2 tangentAt(const Vec2& from, const ProfileElement& element, double s) {
    if (!element.centre) return (element.end - from).normalized();
    const Vec2 centre = *element.centre;
    const double sweep = arcSweep(from, element.end, centre, element.ccw);
    const double angle = std::atan2(from.y() - centre.y(), from.x() - centre.x()) + s * sweep;
    const Vec2 radial(std::cos(angle), std::sin(angle));
    return sweep > 0.0 ? leftNormal(radial) : -leftNormal(radial);
}

}  // namespace

std::optional<UnreachableElement> firstUnreachableElement(
    const Vec2& start, const std::vector<ProfileElement>& profile, const Vec2& feed,
    const Vec2& outward, const InsertGeometry& insert) {
    // Without NOSEA and CUTA only the nose radius is known: only arcs are checked.
    const bool anglesKnown = insert.cuttingAngleDeg > 0.0 && insert.noseAngleDeg > 0.0;
    if (!anglesKnown && insert.noseRadius <= 0.0) return std::nullopt;
    const double wallLimit = insert.cuttingAngleDeg;
    const double descentLimit = 180.0 - insert.cuttingAngleDeg - insert.noseAngleDeg;
    // The profile's outward normal is this side of its tangent.
    const double outwardSide = cross2(feed, outward) > 0.0 ? 1.0 : -1.0;
    Vec2 from = start;
    for (size_t i = 0; i < profile.size(); ++i) {
        const ProfileElement& element = profile[i];
        if ((element.end - from).norm() < 1e-9 && !element.centre) continue;
        const int samples = element.centre ? kArcSamples : 1;
        for (int k = 0; anglesKnown && k <= samples; ++k) {
            const Vec2 t = tangentAt(from, element, static_cast<double>(k) / samples);
            const double slope = radToDeg(std::atan2(t.dot(outward), t.dot(feed)));
            if (slope > wallLimit + kAngleToleranceDeg) {
                return UnreachableElement{UnreachableElement::Kind::WallTooSteep, i, slope,
                                          wallLimit};
            }
            if (-slope > descentLimit + kAngleToleranceDeg) {
                return UnreachableElement{UnreachableElement::Kind::DescentTooSteep, i, -slope,
                                          std::max(descentLimit, 0.0)};
            }
        }
        if (element.centre) {
            // Concave: the centre lies on the outward side of the path.
            const Vec2 t = tangentAt(from, element, 0.0);
            const Vec2 normal = outwardSide * leftNormal(t);
            const double radius = (from - *element.centre).norm();
            const bool concave = (*element.centre - from).dot(normal) > 0.0;
            if (concave && radius < insert.noseRadius - 1e-9) {
                return UnreachableElement{UnreachableElement::Kind::ArcTighterThanNose, i, radius,
                                          insert.noseRadius};
            }
        }
        from = element.end;
    }
    return std::nullopt;
}

}  // namespace kerf::cycles::lathe
