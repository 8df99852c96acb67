#include "core/geometry/fk/fk_carrier.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::fk {

Carrier Carrier::line(const Vec2& point, const Vec2& dir) {
    Carrier c;
    c.point = point;
    c.dir = dir.normalized();
    return c;
}

Carrier Carrier::arc(const Vec2& centre, double radius, bool ccw) {
    Carrier c;
    c.circle = true;
    c.centre = centre;
    c.radius = radius;
    c.ccw = ccw;
    return c;
}

Vec2 Carrier::tangentAt(const Vec2& p) const {
    if (!circle) return dir;
    const Vec2 radial = (p - centre).normalized();
    return ccw ? leftNormal(radial) : Vec2(-leftNormal(radial));
}

double Carrier::distanceTo(const Vec2& p) const {
    if (circle) return std::fabs((p - centre).norm() - radius);
    return std::fabs(cross2(dir, p - point));
}

double Carrier::scale() const {
    const Vec2 where = circle ? centre : point;
    return std::max({1.0, where.cwiseAbs().maxCoeff(), circle ? radius : 0.0});
}

bool Carrier::sameAs(const Carrier& other) const {
    if (circle != other.circle) return false;
    const double tol = kFkTolerance * std::max(scale(), other.scale());
    if (circle) {
        return ccw == other.ccw && (centre - other.centre).norm() <= tol &&
               std::fabs(radius - other.radius) <= tol;
    }
    return (dir - other.dir).norm() <= kFkTolerance && other.distanceTo(point) <= tol;
}

namespace {

void addUnique(std::vector<Vec2>& points, const Vec2& p, double tol) {
    for (const Vec2& q : points)
        if ((q - p).norm() <= tol) return;
    points.push_back(p);
}

std::vector<Vec2> lineCircle(const Carrier& line, const Carrier& circle, double tol) {
    const Vec2 foot = line.point + line.dir * line.dir.dot(circle.centre - line.point);
    const double distance = (foot - circle.centre).norm();
    std::vector<Vec2> out;
    if (distance > circle.radius + tol) return out;
    const double half =
        std::sqrt(std::max(0.0, circle.radius * circle.radius - distance * distance));
    addUnique(out, foot + half * line.dir, tol);
    addUnique(out, foot - half * line.dir, tol);
    return out;
}

std::vector<Vec2> circleCircle(const Carrier& a, const Carrier& b, double tol) {
    std::vector<Vec2> out;
    const Vec2 between = b.centre - a.centre;
    const double d = between.norm();
    if (d <= tol || d > a.radius + b.radius + tol || d < std::fabs(a.radius - b.radius) - tol) {
        return out;
    }
    const Vec2 u = between / d;
    const double along = (d * d + a.radius * a.radius - b.radius * b.radius) / (2.0 * d);
    const double half = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
    const Vec2 mid = a.centre + along * u;
    addUnique(out, mid - half * leftNormal(u), tol);
    addUnique(out, mid + half * leftNormal(u), tol);
    return out;
}

}  // namespace

std::vector<Vec2> intersect(const Carrier& a, const Carrier& b) {
    const double tol = kFkTolerance * std::max(a.scale(), b.scale());
    if (!a.circle && !b.circle) {
        const double denominator = cross2(a.dir, b.dir);
        if (std::fabs(denominator) <= kFkTolerance) return {};
        const double t = cross2(b.point - a.point, b.dir) / denominator;
        return {a.point + t * a.dir};
    }
    if (!a.circle) return lineCircle(a, b, tol);
    if (!b.circle) return lineCircle(b, a, tol);
    return circleCircle(a, b, tol);
}

std::optional<Vec2> touchPoint(const Carrier& from, const Carrier& to) {
    const double tol = kFkTolerance * std::max(from.scale(), to.scale());
    std::optional<Vec2> p;
    if (!from.circle && !to.circle) {
        return std::nullopt;  // collinear lines meet everywhere: no point is singled out
    }
    if (from.circle && to.circle) {
        const Vec2 between = to.centre - from.centre;
        const double d = between.norm();
        if (d <= tol) return std::nullopt;
        const bool external = std::fabs(d - (from.radius + to.radius)) <= tol;
        const bool internal = std::fabs(d - std::fabs(from.radius - to.radius)) <= tol;
        if (!external && !internal) return std::nullopt;
        const Vec2 u = between / d;
        // Inside each other the contact lies on the bigger circle, away from the smaller one.
        p = from.radius >= to.radius || external ? Vec2(from.centre + from.radius * u)
                                                 : Vec2(to.centre - to.radius * u);
    } else {
        const Carrier& line = from.circle ? to : from;
        const Carrier& circle = from.circle ? from : to;
        const Vec2 foot = line.point + line.dir * line.dir.dot(circle.centre - line.point);
        if (std::fabs((foot - circle.centre).norm() - circle.radius) > tol) return std::nullopt;
        p = foot;
    }
    if (!p) return std::nullopt;
    if ((from.tangentAt(*p) - to.tangentAt(*p)).norm() > 1e-6) return std::nullopt;
    return p;
}

std::vector<Vec2> tangentPointsFrom(const Vec2& from, const Vec2& centre, double radius) {
    const Vec2 toCentre = centre - from;
    const double d = toCentre.norm();
    std::vector<Vec2> out;
    if (d <= kFkTolerance || d < radius - kFkTolerance * std::max(1.0, d)) return out;
    const double tangentLength = std::sqrt(std::max(0.0, d * d - radius * radius));
    const Vec2 u = toCentre / d;
    // The touching points seen from `from`: angle asin(r/d) either side of the centre.
    const double sinA = radius / d;
    const double cosA = tangentLength / d;
    const Vec2 right{u.x() * cosA + u.y() * sinA, -u.x() * sinA + u.y() * cosA};
    const Vec2 left{u.x() * cosA - u.y() * sinA, u.x() * sinA + u.y() * cosA};
    addUnique(out, from + tangentLength * right, kFkTolerance * std::max(1.0, d));
    addUnique(out, from + tangentLength * left, kFkTolerance * std::max(1.0, d));
    return out;
}

void orderAlong(std::vector<Vec2>& points, const Vec2& dir) {
    std::stable_sort(points.begin(), points.end(),
                     [&](const Vec2& a, const Vec2& b) { return a.dot(dir) > b.dot(dir); });
}

}  // namespace kerf::fk
