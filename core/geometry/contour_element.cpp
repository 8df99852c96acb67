#include "core/geometry/contour_element.h"

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

constexpr double kEps = 1e-9;

double normalizeAngle(double a) {
    while (a <= -kPi)
        a += kTwoPi;
    while (a > kPi)
        a -= kTwoPi;
    return a;
}

}  // namespace

ContourElement ContourElement::line(Plane plane, const Pose& start, const Pose& end) {
    ContourElement e;
    e.kind = Kind::Line;
    e.plane = plane;
    e.start = start;
    e.end = end;
    return e;
}

ContourElement ContourElement::arc(Plane plane, const Pose& start, const Pose& end,
                                   const Vec2& center, double sweep) {
    ContourElement e;
    e.kind = Kind::Arc;
    e.plane = plane;
    e.start = start;
    e.end = end;
    e.center = center;
    e.sweep = sweep;
    return e;
}

double ContourElement::planarLength() const {
    if (kind == Kind::Line) return (end2() - start2()).norm();
    return radius() * std::fabs(sweep);
}

Vec2 ContourElement::startTangent() const {
    if (kind == Kind::Arc) return arcTangentAt(center, start2(), sweep);
    Vec2 d = end2() - start2();
    double n = d.norm();
    return n > kEps ? Vec2(d / n) : Vec2(1.0, 0.0);
}

Vec2 ContourElement::endTangent() const {
    if (kind == Kind::Arc) return arcTangentAt(center, end2(), sweep);
    return startTangent();
}

Vec2 ContourElement::pointAt(double t) const {
    if (kind == Kind::Line) return start2() + t * (end2() - start2());
    Vec2 r = start2() - center;
    double a = std::atan2(r.y(), r.x()) + t * sweep;
    return center + r.norm() * Vec2(std::cos(a), std::sin(a));
}

Pose ContourElement::poseAt(double t) const {
    if (t == 0.0) return start;
    if (t == 1.0) return end;
    Pose p;
    for (size_t i = 0; i < p.values.size(); ++i) {
        p.values[i] = start.values[i] + t * (end.values[i] - start.values[i]);
    }
    setInPlane(p, pointAt(t));
    return p;
}

double ContourElement::paramOf(const Vec2& p) const {
    if (kind == Kind::Line) {
        Vec2 d = end2() - start2();
        double len2 = d.squaredNorm();
        return len2 > kEps * kEps ? (p - start2()).dot(d) / len2 : 0.0;
    }
    const double span = std::fabs(sweep);
    if (span < kEps) return 0.0;
    Vec2 a = start2() - center;
    Vec2 b = p - center;
    // Angle travelled from the start in the direction of the arc, in [0, 2 pi).
    double travelled = std::atan2(cross2(a, b), a.dot(b)) * (sweep > 0.0 ? 1.0 : -1.0);
    if (travelled < 0.0) travelled += kTwoPi;
    if (travelled <= span) return travelled / span;
    // Beyond the end: report it as after the end or before the start, whichever is nearer.
    const double after = travelled - span;
    const double before = kTwoPi - travelled;
    return after <= before ? travelled / span : -before / span;
}

ContourElement ContourElement::sub(double t0, double t1) const {
    ContourElement e = *this;
    e.start = poseAt(t0);
    e.end = poseAt(t1);
    if (kind == Kind::Arc) e.sweep = sweep * (t1 - t0);
    return e;
}

std::optional<ContourElement> offsetElement(const ContourElement& element, double distance) {
    ContourElement out = element;
    if (element.kind == ContourElement::Kind::Line) {
        Vec2 n = leftNormal(element.startTangent()) * distance;
        element.setInPlane(out.start, element.start2() + n);
        element.setInPlane(out.end, element.end2() + n);
        return out;
    }
    const double r = element.radius();
    // Left of a counter-clockwise arc is towards its centre.
    const double newRadius = element.sweep > 0.0 ? r - distance : r + distance;
    if (newRadius <= kEps || r <= kEps) return std::nullopt;
    const double scale = newRadius / r;
    element.setInPlane(out.start, element.center + (element.start2() - element.center) * scale);
    element.setInPlane(out.end, element.center + (element.end2() - element.center) * scale);
    return out;
}

std::vector<Vec2> intersectCarriers(const ContourElement& a, const ContourElement& b) {
    using Kind = ContourElement::Kind;
    std::vector<Vec2> points;
    if (a.kind == Kind::Line && b.kind == Kind::Line) {
        Vec2 p = a.start2(), r = a.end2() - a.start2();
        Vec2 q = b.start2(), s = b.end2() - b.start2();
        double denom = cross2(r, s);
        if (std::fabs(denom) < 1e-12 * std::max(1.0, r.norm() * s.norm())) return points;
        double t = cross2(q - p, s) / denom;
        points.push_back(p + t * r);
        return points;
    }
    if (a.kind == Kind::Arc && b.kind == Kind::Arc) {
        Vec2 c0 = a.center, c1 = b.center;
        double r0 = a.radius(), r1 = b.radius();
        Vec2 d = c1 - c0;
        double dist = d.norm();
        if (dist < kEps) return points;
        double x = (dist * dist + r0 * r0 - r1 * r1) / (2.0 * dist);
        double h2 = r0 * r0 - x * x;
        if (h2 < -1e-9 * std::max(1.0, r0 * r0)) return points;
        double h = std::sqrt(std::max(0.0, h2));
        Vec2 u = d / dist;
        Vec2 base = c0 + x * u;
        points.push_back(base + h * leftNormal(u));
        if (h > kEps) points.push_back(base - h * leftNormal(u));
        return points;
    }
    const ContourElement& line = a.kind == Kind::Line ? a : b;
    const ContourElement& circle = a.kind == Kind::Line ? b : a;
    Vec2 p = line.start2();
    Vec2 dir = line.end2() - line.start2();
    double len = dir.norm();
    if (len < kEps) return points;
    dir /= len;
    Vec2 f = p - circle.center;
    double r = circle.radius();
    double bq = f.dot(dir);
    double cq = f.squaredNorm() - r * r;
    double disc = bq * bq - cq;
    if (disc < -1e-9 * std::max(1.0, r * r)) return points;
    double root = std::sqrt(std::max(0.0, disc));
    points.push_back(p + (-bq - root) * dir);
    if (root > kEps) points.push_back(p + (-bq + root) * dir);
    return points;
}

double turnAngle(const ContourElement& a, const ContourElement& b) {
    Vec2 t1 = a.endTangent();
    Vec2 t2 = b.startTangent();
    return normalizeAngle(std::atan2(cross2(t1, t2), t1.dot(t2)));
}

std::optional<Fillet> fillet(const ContourElement& a, const ContourElement& b, double radius) {
    if (radius <= kEps) return std::nullopt;
    const double turn = turnAngle(a, b);
    if (std::fabs(turn) < 1e-9 || std::fabs(std::fabs(turn) - kPi) < 1e-9) return std::nullopt;
    // The centre lies on the inside of the corner, `radius` away from both carriers.
    const double side = turn > 0.0 ? radius : -radius;
    auto offA = offsetElement(a, side);
    auto offB = offsetElement(b, side);
    if (!offA || !offB) return std::nullopt;
    const Vec2 corner = a.end2();
    std::vector<Vec2> candidates = intersectCarriers(*offA, *offB);
    std::optional<Fillet> best;
    double bestDistance = 1e300;
    for (const Vec2& c : candidates) {
        // Tangent points: the feet of the centre on both carriers.
        Vec2 footA, footB;
        if (a.kind == ContourElement::Kind::Line) {
            double t = offA->paramOf(c);
            footA = a.pointAt(t);
        } else {
            footA = a.center + (c - a.center).normalized() * a.radius();
        }
        if (b.kind == ContourElement::Kind::Line) {
            double t = offB->paramOf(c);
            footB = b.pointAt(t);
        } else {
            footB = b.center + (c - b.center).normalized() * b.radius();
        }
        double ta = a.paramOf(footA);
        double tb = b.paramOf(footB);
        if (ta < -1e-9 || ta > 1.0 + 1e-9 || tb < -1e-9 || tb > 1.0 + 1e-9) continue;
        double distance = (c - corner).norm();
        if (distance < bestDistance) {
            bestDistance = distance;
            Fillet f;
            f.paramOnA = std::clamp(ta, 0.0, 1.0);
            f.paramOnB = std::clamp(tb, 0.0, 1.0);
            f.center = c;
            f.sweep = arcSweep(footA, footB, c, turn > 0.0);
            best = f;
        }
    }
    return best;
}

}  // namespace kerf
