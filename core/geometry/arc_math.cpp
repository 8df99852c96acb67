#include "core/geometry/arc_math.h"

#include <cmath>

namespace kerf {

double arcSweep(const Vec2& start, const Vec2& end, const Vec2& center, bool ccw) {
    const Vec2 a = start - center;
    const Vec2 b = end - center;
    double sweep = std::atan2(cross2(a, b), a.dot(b));  // (-pi, pi]
    const double scale = std::max(a.norm(), 1e-9);
    const bool coincident = (end - start).norm() <= 1e-9 * std::max(1.0, scale);
    if (ccw) {
        if (coincident || sweep <= 0.0) sweep += kTwoPi;
        if (coincident) sweep = kTwoPi;
    } else {
        if (coincident || sweep >= 0.0) sweep -= kTwoPi;
        if (coincident) sweep = -kTwoPi;
    }
    return sweep;
}

std::optional<Vec2> arcCenterFromRadius(const Vec2& start, const Vec2& end, double signedRadius,
                                        bool ccw) {
    const Vec2 chord = end - start;
    const double length = chord.norm();
    const double radius = std::fabs(signedRadius);
    if (length < 1e-9 || radius < 1e-9) return std::nullopt;
    double half = length / 2.0;
    double h2 = radius * radius - half * half;
    if (h2 < 0.0) {
        // Accept chords a hair longer than the diameter (rounded program values): a half circle.
        if (half - radius > 1e-4 * std::max(1.0, radius)) return std::nullopt;
        h2 = 0.0;
    }
    const double h = std::sqrt(h2);
    const Vec2 mid = start + chord / 2.0;
    const Vec2 left = leftNormal(chord / length);
    // For a counter-clockwise arc of at most 180 degrees the centre lies left of the chord.
    const bool small = signedRadius > 0.0;
    const double side = (ccw == small) ? 1.0 : -1.0;
    return mid + side * h * left;
}

std::optional<TangentArc> tangentArc(const Vec2& start, const Vec2& tangent, const Vec2& end) {
    const Vec2 chord = end - start;
    const Vec2 normal = leftNormal(tangent);
    const double denominator = 2.0 * chord.dot(normal);
    if (std::fabs(denominator) < 1e-12 * std::max(1.0, chord.squaredNorm())) return std::nullopt;
    // Signed radius along the left normal: |start + r n - end| = |r|.
    const double r = chord.squaredNorm() / denominator;
    TangentArc arc;
    arc.center = start + r * normal;
    arc.sweep = arcSweep(start, end, arc.center, r > 0.0);
    return arc;
}

Vec2 arcTangentAt(const Vec2& center, const Vec2& point, double sweep) {
    Vec2 radial = point - center;
    double norm = radial.norm();
    if (norm < 1e-15) return {1.0, 0.0};
    Vec2 t = leftNormal(radial / norm);
    return sweep >= 0.0 ? t : Vec2(-t);
}

void addArcExtremes(Box2& box, const Vec2& center, const Vec2& start, double sweep) {
    const Vec2 radial = start - center;
    const double radius = radial.norm();
    const double a0 = std::atan2(radial.y(), radial.x());
    const double a1 = a0 + sweep;
    box.add(start);
    box.add(center + radius * Vec2(std::cos(a1), std::sin(a1)));
    const double lo = std::min(a0, a1);
    const double hi = std::max(a0, a1);
    // Quadrant angles k * pi/2 inside [lo, hi].
    const double quarter = kPi / 2.0;
    for (double k = std::ceil(lo / quarter); k * quarter <= hi; k += 1.0) {
        const double angle = k * quarter;
        box.add(center + radius * Vec2(std::cos(angle), std::sin(angle)));
    }
}

std::optional<Circle> circleThrough(const Vec2& a, const Vec2& b, const Vec2& c) {
    const double d = 2.0 * cross2(b - a, c - a);
    if (std::fabs(d) < 1e-12) return std::nullopt;
    const Vec2 ab = b - a;
    const Vec2 ac = c - a;
    const double ab2 = ab.squaredNorm();
    const double ac2 = ac.squaredNorm();
    const Vec2 offset((ac.y() * ab2 - ab.y() * ac2) / d, (ab.x() * ac2 - ac.x() * ab2) / d);
    return Circle{a + offset, offset.norm()};
}

}  // namespace kerf
