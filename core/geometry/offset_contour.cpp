#include "core/geometry/offset_contour.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace kerf {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSame = 1e-9;  // mm: points closer than this are one point

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

Vec2 rotated(const Vec2& p, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

// Counter-clockwise angle from direction a to direction b, in [0, 2 pi).
double ccwAngle(const Vec2& a, const Vec2& b) {
    double angle = std::atan2(cross(a, b), a.dot(b));
    if (angle < 0.0) angle += 2.0 * kPi;
    return angle;
}

PlanarSegment arcThrough(const Vec2& start, const Vec2& end, const Vec2& center, double sweep) {
    return {PlanarSegment::Kind::Arc, start, end, center, sweep};
}

}  // namespace

// Intersections of the carriers (infinite line, full circle) of two segments.
std::vector<Vec2> carrierIntersections(const PlanarSegment& a, const PlanarSegment& b) {
    using Kind = PlanarSegment::Kind;
    std::vector<Vec2> out;
    if (a.kind == Kind::Line && b.kind == Kind::Line) {
        const Vec2 da = a.end - a.start;
        const Vec2 db = b.end - b.start;
        const double det = cross(da, db);
        if (std::fabs(det) < 1e-14) return out;
        const double t = cross(b.start - a.start, db) / det;
        out.push_back(a.start + t * da);
        return out;
    }
    if (a.kind == Kind::Arc && b.kind == Kind::Line) return carrierIntersections(b, a);
    if (a.kind == Kind::Line) {
        const Vec2 d = (a.end - a.start).normalized();
        const Vec2 f = a.start - b.center;
        const double along = -f.dot(d);
        const double r = b.radius();
        const double h2 = r * r - (f.squaredNorm() - along * along);
        if (h2 < -1e-12) return out;
        const double h = std::sqrt(std::max(0.0, h2));
        out.push_back(a.start + (along - h) * d);
        out.push_back(a.start + (along + h) * d);
        return out;
    }
    const Vec2 dc = b.center - a.center;
    const double dist = dc.norm();
    const double ra = a.radius();
    const double rb = b.radius();
    if (dist < 1e-12) return out;
    const double x = (dist * dist + ra * ra - rb * rb) / (2.0 * dist);
    const double h2 = ra * ra - x * x;
    if (h2 < -1e-12) return out;
    const double h = std::sqrt(std::max(0.0, h2));
    const Vec2 u = dc / dist;
    const Vec2 n(-u.y(), u.x());
    out.push_back(a.center + x * u + h * n);
    out.push_back(a.center + x * u - h * n);
    return out;
}

PlanarSegment PlanarSegment::line(const Vec2& start, const Vec2& end) {
    return {Kind::Line, start, end, Vec2(0.0, 0.0), 0.0};
}

PlanarSegment PlanarSegment::arc(const Vec2& start, const Vec2& center, double sweep) {
    return arcThrough(start, center + rotated(start - center, sweep), center, sweep);
}

double PlanarSegment::length() const {
    return kind == Kind::Line ? (end - start).norm() : radius() * std::fabs(sweep);
}

Vec2 PlanarSegment::startTangent() const {
    if (kind == Kind::Line) return (end - start).normalized();
    const Vec2 r = (start - center).normalized();
    return sweep >= 0.0 ? Vec2(-r.y(), r.x()) : Vec2(r.y(), -r.x());
}

Vec2 PlanarSegment::endTangent() const {
    if (kind == Kind::Line) return (end - start).normalized();
    const Vec2 r = (end - center).normalized();
    return sweep >= 0.0 ? Vec2(-r.y(), r.x()) : Vec2(r.y(), -r.x());
}

PlanarSegment PlanarSegment::reversed() const {
    return {kind, end, start, center, -sweep};
}

double PlanarSegment::distanceTo(const Vec2& p) const {
    if (kind == Kind::Line) {
        const Vec2 d = end - start;
        const double len2 = d.squaredNorm();
        const double t = len2 > 0.0 ? std::clamp((p - start).dot(d) / len2, 0.0, 1.0) : 0.0;
        return (start + t * d - p).norm();
    }
    // Inside the swept angle the nearest point is on the circle, else an end point.
    const Vec2 from = sweep >= 0.0 ? start - center : end - center;
    const double along = ccwAngle(from, p - center);
    if (along <= std::fabs(sweep) && (p - center).norm() > 0.0) {
        return std::fabs((p - center).norm() - radius());
    }
    return std::min((p - start).norm(), (p - end).norm());
}

double ClosedContour::signedArea() const {
    double area = 0.0;
    for (const PlanarSegment& s : segments) {
        area += cross(s.start, s.end) / 2.0;
        if (s.kind == PlanarSegment::Kind::Arc) {
            const double r = s.radius();
            const double t = std::fabs(s.sweep);
            area += (s.sweep >= 0.0 ? 1.0 : -1.0) * r * r * (t - std::sin(t)) / 2.0;
        }
    }
    return area;
}

ClosedContour ClosedContour::reversed() const {
    ClosedContour out;
    out.segments.reserve(segments.size());
    for (auto it = segments.rbegin(); it != segments.rend(); ++it)
        out.segments.push_back(it->reversed());
    return out;
}

ClosedContour ClosedContour::placed(const Vec2& offset, double angleRad) const {
    ClosedContour out = *this;
    for (PlanarSegment& s : out.segments) {
        s.start = offset + rotated(s.start, angleRad);
        s.end = offset + rotated(s.end, angleRad);
        s.center = offset + rotated(s.center, angleRad);
    }
    return out;
}

double ClosedContour::distanceTo(const Vec2& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const PlanarSegment& s : segments)
        best = std::min(best, s.distanceTo(p));
    return best;
}

ClosedContour roundedRectangle(double length, double width, double cornerRadius) {
    const double hl = length / 2.0;
    const double hw = width / 2.0;
    const bool chamfer = cornerRadius < 0.0;
    const double c = std::min(std::fabs(cornerRadius), std::min(hl, hw));
    // The four corners counter-clockwise from +u+v, each with the directions of its two sides.
    const Vec2 corners[4] = {{hl, hw}, {-hl, hw}, {-hl, -hw}, {hl, -hw}};
    const Vec2 inbound[4] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};  // travel into the corner
    ClosedContour out;
    Vec2 at(hl, 0.0);
    auto lineTo = [&](const Vec2& p) {
        if ((p - at).norm() > kSame) out.segments.push_back(PlanarSegment::line(at, p));
        at = p;
    };
    for (int k = 0; k < 4; ++k) {
        const Vec2 in = inbound[k];
        const Vec2 out2 = inbound[(k + 1) % 4];
        const Vec2 before = corners[k] - c * in;
        const Vec2 after = corners[k] + c * out2;
        lineTo(before);
        if (c > kSame) {
            if (chamfer) {
                lineTo(after);
            } else {
                out.segments.push_back(PlanarSegment::arc(before, before + c * out2, kPi / 2.0));
                at = after;
            }
        }
    }
    lineTo(Vec2(hl, 0.0));
    return out;
}

ClosedContour arcSlot(double pitchRadius, double startRad, double sweepRad, double width) {
    const double half = width / 2.0;
    auto unit = [](double a) { return Vec2(std::cos(a), std::sin(a)); };
    const double endRad = startRad + sweepRad;
    const Vec2 startCentre = pitchRadius * unit(startRad);
    const Vec2 endCentre = pitchRadius * unit(endRad);
    const Vec2 tangent = unit(endRad + kPi / 2.0);
    ClosedContour out;
    auto add = [&](const PlanarSegment& s) {
        if (std::fabs(s.sweep) * s.radius() > kSame) out.segments.push_back(s);
    };
    const Vec2 origin(0.0, 0.0);
    add(PlanarSegment::arc(endCentre + half * tangent, endCentre, kPi / 2.0));
    add(PlanarSegment::arc((pitchRadius - half) * unit(endRad), origin, -sweepRad));
    add(PlanarSegment::arc((pitchRadius - half) * unit(startRad), startCentre, kPi));
    add(PlanarSegment::arc((pitchRadius + half) * unit(startRad), origin, sweepRad));
    add(PlanarSegment::arc((pitchRadius + half) * unit(endRad), endCentre, kPi / 2.0));
    return out;
}

std::optional<ClosedContour> regularPolygon(double circumradius, int corners, double cornerRadius) {
    if (corners < 3) return std::nullopt;
    const double step = 2.0 * kPi / corners;
    const double halfSide = circumradius * std::sin(step / 2.0);
    // Along each side, how far from the corner the rounding or the chamfer starts.
    const double cut = cornerRadius >= 0.0 ? cornerRadius * std::tan(step / 2.0) : -cornerRadius;
    if (cut > halfSide + kSame) return std::nullopt;
    ClosedContour out;
    Vec2 at(circumradius * std::cos(step / 2.0), 0.0);
    auto lineTo = [&](const Vec2& p) {
        if ((p - at).norm() > kSame) out.segments.push_back(PlanarSegment::line(at, p));
        at = p;
    };
    for (int k = 0; k < corners; ++k) {
        const double angle = step / 2.0 + k * step;
        const Vec2 corner = circumradius * Vec2(std::cos(angle), std::sin(angle));
        const Vec2 in = Vec2(-std::sin(angle - step / 2.0), std::cos(angle - step / 2.0));
        const Vec2 out2 = Vec2(-std::sin(angle + step / 2.0), std::cos(angle + step / 2.0));
        lineTo(corner - cut * in);
        if (cut <= kSame) continue;
        if (cornerRadius < 0.0) {
            lineTo(corner + cut * out2);
        } else {
            const Vec2 centre = at + cornerRadius * Vec2(-in.y(), in.x());
            out.segments.push_back(PlanarSegment::arc(at, centre, step));
            at = corner + cut * out2;
        }
    }
    lineTo(Vec2(circumradius * std::cos(step / 2.0), 0.0));
    return out;
}

ClosedContour circleContour(double radius) {
    ClosedContour out;
    out.segments.push_back(PlanarSegment::arc({radius, 0.0}, {0.0, 0.0}, 2.0 * kPi));
    return out;
}

std::optional<ClosedContour> offsetClosed(const ClosedContour& contour, double distance) {
    struct Piece {
        PlanarSegment s;
        size_t original;
    };
    // Sharp concave corners need trimming outwards and joining arcs inwards: the general case.
    const size_t count = contour.segments.size();
    for (size_t i = 0; i < count; ++i) {
        const Vec2 out = contour.segments[i].endTangent();
        const Vec2 in = contour.segments[(i + 1) % count].startTangent();
        if (cross(out, in) < -1e-9) return std::nullopt;
    }
    std::vector<Piece> pieces;
    for (size_t i = 0; i < count; ++i) {
        const PlanarSegment& s = contour.segments[i];
        if (s.kind == PlanarSegment::Kind::Line) {
            const Vec2 d = s.startTangent();
            const Vec2 right(d.y(), -d.x());
            pieces.push_back(
                {PlanarSegment::line(s.start + distance * right, s.end + distance * right), i});
            continue;
        }
        // A counter-clockwise arc bulges outwards and grows with the distance; a clockwise one
        // (a concave stretch joined tangentially, the inner wall of a circular slot) shrinks.
        const double r = s.radius();
        const double grown = s.sweep > 0.0 ? r + distance : r - distance;
        if (grown <= kSame) continue;  // the arc shrinks to nothing
        const double k = grown / r;
        pieces.push_back({arcThrough(s.center + k * (s.start - s.center),
                                     s.center + k * (s.end - s.center), s.center, s.sweep),
                          i});
    }
    if (pieces.empty()) return std::nullopt;
    ClosedContour out;
    const size_t n = pieces.size();
    if (distance >= 0.0) {
        for (size_t i = 0; i < n; ++i) {
            const PlanarSegment& a = pieces[i].s;
            const PlanarSegment& b = pieces[(i + 1) % n].s;
            out.segments.push_back(a);
            if ((a.end - b.start).norm() <= kSame) continue;
            // A convex corner: an arc about the corner joins the two offsets.
            const Vec2 corner = contour.segments[pieces[i].original].end;
            const double sweep = ccwAngle(a.end - corner, b.start - corner);
            out.segments.push_back(arcThrough(a.end, b.start, corner, sweep));
        }
        return out;
    }
    // Inwards: cut neighbours at the intersection of their carriers nearest the gap.
    for (size_t i = 0; i < n; ++i) {
        PlanarSegment& a = pieces[i].s;
        PlanarSegment& b = pieces[(i + 1) % n].s;
        if ((a.end - b.start).norm() <= kSame) continue;
        const Vec2 gap = (a.end + b.start) / 2.0;
        const std::vector<Vec2> hits = carrierIntersections(a, b);
        if (hits.empty()) return std::nullopt;
        Vec2 best = hits.front();
        for (const Vec2& h : hits) {
            if ((h - gap).norm() < (best - gap).norm()) best = h;
        }
        a.end = best;
        b.start = best;
    }
    for (const Piece& p : pieces) {
        const PlanarSegment& original = contour.segments[p.original];
        PlanarSegment s = p.s;
        if (s.kind == PlanarSegment::Kind::Line) {
            // A line that turned round means the offset lost this side.
            if ((s.end - s.start).dot(original.end - original.start) <= 0.0) return std::nullopt;
        } else {
            const bool ccw = original.sweep > 0.0;
            double sweep = ccw ? ccwAngle(s.start - s.center, s.end - s.center)
                               : ccwAngle(s.end - s.center, s.start - s.center);
            if (sweep <= kSame) {
                if (std::fabs(original.sweep) <= kPi) continue;  // cut down to its point
                sweep = 2.0 * kPi;
            }
            if (sweep > std::fabs(original.sweep) + 1e-9) return std::nullopt;
            s.sweep = ccw ? sweep : -sweep;
        }
        out.segments.push_back(s);
    }
    // Sides that met without turning round can still enclose nothing (a slot's centre line).
    if (out.signedArea() <= kSame) return std::nullopt;
    return out;
}

}  // namespace kerf
