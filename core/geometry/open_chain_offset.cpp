#include "core/geometry/open_chain_offset.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"
#include "core/geometry/segment_intersection.h"

namespace kerf {

namespace {

constexpr double kSame = 1e-9;  // mm: points closer than this are one point

// The segment moved sideways by `distance` (left positive). An arc whose inner side is smaller
// than the distance turns inside out: the points at that distance lie beyond its centre.
std::optional<PlanarSegment> offsetSegment(const PlanarSegment& s, double distance) {
    if (s.kind == PlanarSegment::Kind::Line) {
        const Vec2 shift = distance * leftNormal(s.startTangent());
        return PlanarSegment::line(s.start + shift, s.end + shift);
    }
    // The left of a counter-clockwise arc is its centre.
    const double r = s.radius();
    const double scale = (s.sweep > 0.0 ? r - distance : r + distance) / r;
    if (std::fabs(scale) * r < kSame) return std::nullopt;
    return PlanarSegment{PlanarSegment::Kind::Arc, s.center + scale * (s.start - s.center),
                         s.center + scale * (s.end - s.center), s.center, s.sweep};
}

// The signed angle an arc turns from `from` to `to` in its own direction, in [0, 2 pi) for a
// counter-clockwise arc and (-2 pi, 0] for a clockwise one.
double sweepBetween(const PlanarSegment& arc, const Vec2& from, const Vec2& to) {
    const Vec2 u = from - arc.center;
    const Vec2 v = to - arc.center;
    double angle = std::atan2(cross2(u, v), u.dot(v));
    if (arc.sweep > 0.0 && angle < 0.0) angle += kTwoPi;
    if (arc.sweep < 0.0 && angle > 0.0) angle -= kTwoPi;
    return angle;
}

// Where `p`, a point on the carrier of `s`, lies along it: 0 at the start, 1 at the end; empty
// when it is off the segment.
std::optional<double> along(const PlanarSegment& s, const Vec2& p) {
    if ((p - s.start).norm() < kSame) return 0.0;
    if ((p - s.end).norm() < kSame) return 1.0;
    double t = 0.0;
    if (s.kind == PlanarSegment::Kind::Line) {
        const Vec2 d = s.end - s.start;
        t = (p - s.start).dot(d) / d.squaredNorm();
    } else {
        t = sweepBetween(s, s.start, p) / s.sweep;
    }
    if (t < 0.0 || t > 1.0) return std::nullopt;
    return t;
}

Vec2 pointAt(const PlanarSegment& s, double t) {
    if (s.kind == PlanarSegment::Kind::Line) return s.start + t * (s.end - s.start);
    const double a = t * s.sweep;
    const Vec2 r = s.start - s.center;
    return s.center + Vec2(std::cos(a) * r.x() - std::sin(a) * r.y(),
                           std::sin(a) * r.x() + std::cos(a) * r.y());
}

PlanarSegment piece(const PlanarSegment& s, double t0, double t1) {
    if (s.kind == PlanarSegment::Kind::Line) {
        return PlanarSegment::line(pointAt(s, t0), pointAt(s, t1));
    }
    return {PlanarSegment::Kind::Arc, pointAt(s, t0), pointAt(s, t1), s.center,
            (t1 - t0) * s.sweep};
}

// The offset before its loops are removed: every element moved, convex corners joined by arcs
// about the corner, concave ones by a line (it lies within the distance of the corner).
std::vector<PlanarSegment> rawOffset(const std::vector<PlanarSegment>& chain, double distance) {
    std::vector<PlanarSegment> raw;
    std::optional<Vec2> previousEnd;  // of the previous element moved
    const PlanarSegment* original = nullptr;
    for (const PlanarSegment& s : chain) {
        const std::optional<PlanarSegment> moved = offsetSegment(s, distance);
        // An arc of the offset's radius shrinks to its centre: the corners before and after it
        // join there (a chain offset out and back rounds a cusp about that point).
        const Vec2 start = moved ? moved->start : s.center;
        const Vec2 end = moved ? moved->end : s.center;
        if (previousEnd && (*previousEnd - start).norm() >= kSame) {
            // Convexity is the chain's, not the offsets' (an arc turned inside out runs back).
            const double turn = cross2(original->endTangent(), s.startTangent());
            const bool convex = distance > 0.0 ? turn < 0.0 : turn > 0.0;
            const Vec2 u = *previousEnd - s.start;
            const Vec2 v = start - s.start;
            const double angle = std::fabs(std::atan2(cross2(u, v), u.dot(v)));
            if (convex && std::fabs(u.norm() - std::fabs(distance)) < 1e-6) {
                raw.push_back({PlanarSegment::Kind::Arc, *previousEnd, start, s.start,
                               distance > 0.0 ? -angle : angle});
            } else {
                raw.push_back(PlanarSegment::line(*previousEnd, start));
            }
        }
        if (moved) raw.push_back(*moved);
        previousEnd = end;
        original = &s;
    }
    return raw;
}

Box2 boxOf(const PlanarSegment& s) {
    Box2 box;
    box.add(s.start);
    box.add(s.end);
    if (s.kind == PlanarSegment::Kind::Arc) addArcExtremes(box, s.center, s.start, s.sweep);
    return box;
}

bool overlap(const Box2& a, const Box2& b) {
    constexpr double m = 1e-6;
    return a.min.x() <= b.max.x() + m && b.min.x() <= a.max.x() + m && a.min.y() <= b.max.y() + m &&
           b.min.y() <= a.max.y() + m;
}

// Whether p lies closer than `distance` to the chain (boxes first: most elements are far).
bool closerThan(const std::vector<PlanarSegment>& chain, const std::vector<Box2>& boxes,
                const Vec2& p, double distance) {
    for (size_t i = 0; i < chain.size(); ++i) {
        const Box2& b = boxes[i];
        if (p.x() < b.min.x() - distance || p.x() > b.max.x() + distance ||
            p.y() < b.min.y() - distance || p.y() > b.max.y() + distance) {
            continue;
        }
        if (chain[i].distanceTo(p) < distance) return true;
    }
    return false;
}

// Where `s` first crosses the line `coordinate axis = limit` moving in `direction`, as a place
// along it (0 to 1).
std::optional<double> firstCrossing(const PlanarSegment& s, int axis, double limit,
                                    double direction) {
    Vec2 a(limit, -1.0);
    Vec2 b(limit, 1.0);
    if (axis == 1) a = Vec2(-1.0, limit), b = Vec2(1.0, limit);
    std::optional<double> first;
    for (const Vec2& hit : carrierIntersections(s, PlanarSegment::line(a, b))) {
        const std::optional<double> t = along(s, hit);
        if (!t) continue;
        const Vec2 tangent = s.kind == PlanarSegment::Kind::Line
                                 ? s.startTangent()
                                 : arcTangentAt(s.center, hit, s.sweep);
        if (direction * tangent[axis] > 0.0 && (!first || *t < *first)) first = t;
    }
    return first;
}

// The pieces of a raw offset that lie on the chain's outer boundary: the raw offset is split
// wherever it crosses itself or one of `endCuts` (lines or circles about the chain's ends), and
// a piece is kept unless `tooClose` says its middle lies closer to the chain than the offset
// allows (the piece then belongs to a loop that cuts into the chain). Empty when the kept pieces
// do not form one chain.
template <typename TooClose>
std::optional<std::vector<PlanarSegment>> outerPieces(const std::vector<PlanarSegment>& raw,
                                                      const std::vector<PlanarSegment>& endCuts,
                                                      const TooClose& tooClose) {
    std::vector<std::vector<double>> cuts(raw.size());
    std::vector<Box2> boxes;
    boxes.reserve(raw.size());
    for (const PlanarSegment& s : raw)
        boxes.push_back(boxOf(s));
    // Sweep along u: only elements whose boxes overlap along u are compared.
    std::vector<size_t> order(raw.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return boxes[a].min.x() < boxes[b].min.x(); });
    for (size_t a = 0; a < order.size(); ++a) {
        const size_t i = order[a];
        for (size_t b = a + 1; b < order.size(); ++b) {
            const size_t j = order[b];
            if (boxes[j].min.x() > boxes[i].max.x() + 1e-6) break;
            if (!overlap(boxes[i], boxes[j])) continue;
            for (const Vec2& hit : carrierIntersections(raw[i], raw[j])) {
                const std::optional<double> ti = along(raw[i], hit);
                const std::optional<double> tj = along(raw[j], hit);
                if (!ti || !tj) continue;
                cuts[i].push_back(*ti);
                cuts[j].push_back(*tj);
            }
        }
    }
    for (const PlanarSegment& cut : endCuts) {
        for (size_t i = 0; i < raw.size(); ++i) {
            for (const Vec2& hit : carrierIntersections(raw[i], cut)) {
                if (const std::optional<double> t = along(raw[i], hit)) cuts[i].push_back(*t);
            }
        }
    }
    std::vector<PlanarSegment> out;
    for (size_t i = 0; i < raw.size(); ++i) {
        std::vector<double>& t = cuts[i];
        t.push_back(0.0);
        t.push_back(1.0);
        std::sort(t.begin(), t.end());
        for (size_t k = 0; k + 1 < t.size(); ++k) {
            if (piece(raw[i], t[k], t[k + 1]).length() < kSame) continue;
            if (tooClose(pointAt(raw[i], (t[k] + t[k + 1]) / 2.0))) continue;
            const PlanarSegment part = piece(raw[i], t[k], t[k + 1]);
            if (!out.empty() && (out.back().end - part.start).norm() > 1e-6) return std::nullopt;
            out.push_back(part);
            if (out.size() > 1) out.back().start = out[out.size() - 2].end;
        }
    }
    return out;
}

// Whether the segment has a point strictly inside the box (lines clipped against it, arcs
// through its edges or with an end inside).
bool entersBox(const PlanarSegment& s, const Box2& box) {
    auto inside = [&](const Vec2& p) {
        return p.x() > box.min.x() && p.x() < box.max.x() && p.y() > box.min.y() &&
               p.y() < box.max.y();
    };
    if (inside(s.start) || inside(s.end)) return true;
    if (s.kind == PlanarSegment::Kind::Line) {
        // Liang-Barsky: the part of the line within the box's slabs.
        double t0 = 0.0;
        double t1 = 1.0;
        const Vec2 d = s.end - s.start;
        for (int axis = 0; axis < 2; ++axis) {
            if (std::fabs(d[axis]) < 1e-15) {
                if (s.start[axis] <= box.min[axis] || s.start[axis] >= box.max[axis]) return false;
                continue;
            }
            double a = (box.min[axis] - s.start[axis]) / d[axis];
            double b = (box.max[axis] - s.start[axis]) / d[axis];
            if (a > b) std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
        }
        return t1 > t0;
    }
    const Vec2 corners[] = {box.min, Vec2(box.max.x(), box.min.y()), box.max,
                            Vec2(box.min.x(), box.max.y())};
    for (int k = 0; k < 4; ++k) {
        const PlanarSegment edge = PlanarSegment::line(corners[k], corners[(k + 1) % 4]);
        for (const Vec2& hit : carrierIntersections(s, edge)) {
            if (along(s, hit) && along(edge, hit)) {
                // A touch at a corner or along an edge is not inside: look just past it.
                const Vec2 mid = 0.5 * (box.min + box.max);
                if (inside(hit + 1e-9 * (mid - hit))) return true;
            }
        }
    }
    return false;
}

// The arc cut at every quadrant point it passes, so that over each piece the direction of its
// normal keeps the signs of its components.
void splitAtQuadrants(const PlanarSegment& s, std::vector<PlanarSegment>& out) {
    if (s.kind == PlanarSegment::Kind::Line) {
        out.push_back(s);
        return;
    }
    const double a0 = std::atan2(s.start.y() - s.center.y(), s.start.x() - s.center.x());
    std::vector<double> t{0.0, 1.0};
    for (int k = -8; k <= 8; ++k) {
        const double f = (k * kPi / 2.0 - a0) / s.sweep;
        if (f > 1e-9 && f < 1.0 - 1e-9) t.push_back(f);
    }
    std::sort(t.begin(), t.end());
    for (size_t k = 0; k + 1 < t.size(); ++k)
        out.push_back(piece(s, t[k], t[k + 1]));
}

Vec2 tangentAt(const PlanarSegment& s, double t) {
    return s.kind == PlanarSegment::Kind::Line ? s.startTangent()
                                               : arcTangentAt(s.center, pointAt(s, t), s.sweep);
}

// The corner of the box a point of a segment moves to, where `normal` points to the offset side
// and `tangent` along the travel: the box's far side in each direction the normal has; along a
// direction the normal lacks, the side behind the travel at the segment's start (`atEnd` false)
// and the side ahead at its end, so that the segment is stretched over the box's width.
Vec2 boxCorner(const Box2& box, const Vec2& normal, const Vec2& tangent, bool atEnd) {
    Vec2 corner;
    for (int axis = 0; axis < 2; ++axis) {
        constexpr double kFlat = 1e-12;
        const double n =
            std::fabs(normal[axis]) > kFlat ? normal[axis] : (atEnd ? 1.0 : -1.0) * tangent[axis];
        corner[axis] = n > 0.0 ? box.max[axis] : box.min[axis];
    }
    return corner;
}

}  // namespace

std::optional<std::vector<PlanarSegment>> offsetOpenChain(const std::vector<PlanarSegment>& chain,
                                                          double distance) {
    if (std::fabs(distance) < kSame) return chain;
    // The raw offset is also cut where it enters the circles about the chain's ends, within
    // which it would come closer to an end point than the distance.
    std::vector<PlanarSegment> endCuts;
    for (const Vec2& end : {chain.front().start, chain.back().end}) {
        const Vec2 rim = end + Vec2(std::fabs(distance), 0.0);
        endCuts.push_back({PlanarSegment::Kind::Arc, rim, rim, end, kTwoPi});
    }
    const double keep = std::fabs(distance) - 1e-7;
    std::vector<Box2> chainBoxes;
    chainBoxes.reserve(chain.size());
    for (const PlanarSegment& s : chain)
        chainBoxes.push_back(boxOf(s));
    return outerPieces(rawOffset(chain, distance), endCuts, [&](const Vec2& middle) {
        return closerThan(chain, chainBoxes, middle, keep);
    });
}

std::optional<std::vector<PlanarSegment>> offsetOpenChainByBox(
    const std::vector<PlanarSegment>& chain, Box2 box, double side) {
    // A side of zero width is widened a little, so that the loops a flat box leaves lying on
    // the chain still enclose something and are recognised.
    constexpr double kThin = 1e-6;
    box.min = box.min.cwiseMin(Vec2(-kThin, -kThin));
    box.max = box.max.cwiseMax(Vec2(kThin, kThin));
    std::vector<PlanarSegment> pieces;
    for (const PlanarSegment& s : chain)
        splitAtQuadrants(s, pieces);
    // Every piece moved by the box corner its normal points to; consecutive pieces joined along
    // the box's edges, through the corner farther out where they differ in both directions.
    std::vector<PlanarSegment> raw;
    for (const PlanarSegment& s : pieces) {
        const Vec2 normal = side * leftNormal(tangentAt(s, 0.5));
        const Vec2 from = s.start + boxCorner(box, normal, tangentAt(s, 0.0), false);
        const Vec2 to = s.end + boxCorner(box, normal, tangentAt(s, 1.0), true);
        if (!raw.empty() && (raw.back().end - from).norm() >= kSame) {
            const Vec2 last = raw.back().end;
            const Vec2 a(last.x(), from.y());
            const Vec2 b(from.x(), last.y());
            const Vec2 via = (a - s.start).dot(normal) >= (b - s.start).dot(normal) ? a : b;
            for (const Vec2& p : {via, from}) {
                if ((raw.back().end - p).norm() >= kSame)
                    raw.push_back(PlanarSegment::line(raw.back().end, p));
            }
        }
        if (s.kind == PlanarSegment::Kind::Line) {
            raw.push_back(PlanarSegment::line(from, to));
        } else {
            const Vec2 shift = from - s.start;
            raw.push_back({PlanarSegment::Kind::Arc, from, to, s.center + shift, s.sweep});
        }
    }
    // The edges of the boxes about the chain's ends.
    std::vector<PlanarSegment> endCuts;
    for (const Vec2& end : {chain.front().start, chain.back().end}) {
        const Vec2 lo = end + box.min;
        const Vec2 hi = end + box.max;
        endCuts.push_back(PlanarSegment::line(lo, Vec2(hi.x(), lo.y())));
        endCuts.push_back(PlanarSegment::line(lo, Vec2(lo.x(), hi.y())));
        endCuts.push_back(PlanarSegment::line(hi, Vec2(hi.x(), lo.y())));
        endCuts.push_back(PlanarSegment::line(hi, Vec2(lo.x(), hi.y())));
    }
    // A point is too close when a point of the chain lies strictly inside the box placed
    // behind it (the points that put it within the box of the chain).
    constexpr double kMargin = 1e-7;
    const auto kept = outerPieces(raw, endCuts, [&](const Vec2& middle) {
        Box2 around;
        around.min = middle - box.max + Vec2(kMargin, kMargin);
        around.max = middle - box.min - Vec2(kMargin, kMargin);
        for (const PlanarSegment& s : chain) {
            if (entersBox(s, around)) return true;
        }
        return false;
    });
    if (!kept) return kept;
    // The cuts leave lines and arcs in several pieces: one line or arc each.
    auto continues = [](const PlanarSegment& a, const PlanarSegment& b) {
        if (a.kind != b.kind) return false;
        if (a.kind == PlanarSegment::Kind::Arc) {
            return (a.center - b.center).norm() < 1e-9 && (a.sweep > 0.0) == (b.sweep > 0.0);
        }
        return std::fabs(cross2(a.startTangent(), b.startTangent())) < 1e-12 &&
               a.startTangent().dot(b.startTangent()) > 0.0;
    };
    std::vector<PlanarSegment> out;
    for (const PlanarSegment& s : *kept) {
        if (!out.empty() && continues(out.back(), s)) {
            out.back().end = s.end;
            out.back().sweep += s.sweep;
        } else {
            out.push_back(s);
        }
    }
    return out;
}

std::vector<PlanarSegment> chainUpTo(const std::vector<PlanarSegment>& chain, int axis,
                                     double limit, double direction) {
    std::vector<PlanarSegment> out;
    if (chain.empty() || direction * (chain.front().start[axis] - limit) > kSame) return out;
    for (const PlanarSegment& s : chain) {
        const std::optional<double> crossing = firstCrossing(s, axis, limit, direction);
        if (!crossing) {
            out.push_back(s);
            continue;
        }
        if (*crossing > 0.0) out.push_back(piece(s, 0.0, *crossing));
        break;
    }
    return out;
}

}  // namespace kerf
