#include "motion/planner/polyline_smoother.h"

#include <algorithm>
#include <cmath>

#include "motion/planner/biarc.h"

namespace kerf::motion {

namespace {

using V3 = Vec3Array;

constexpr double kPi = 3.14159265358979323846;

V3 xyz(const AxisVector& p) {
    return {p[0], p[1], p[2]};
}
V3 sub(const V3& a, const V3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 unit(const V3& a) {
    double n = std::sqrt(dot(a, a));
    return n > 0.0 ? V3{a[0] / n, a[1] / n, a[2] / n} : V3{};
}
// Unit vector of the combination w0 u0 + w1 u1 of two unit vectors.
V3 combined(double w0, const V3& u0, double w1, const V3& u1) {
    return unit({w0 * u0[0] + w1 * u1[0], w0 * u0[1] + w1 * u1[1], w0 * u0[2] + w1 * u1[2]});
}

// Distance of p from one arc of a biarc (or the line a degenerate one is), in closed form.
double arcDistance(const PathGeometry& g, const V3& p) {
    if (!g.curved()) return distanceTo(g, p, 0.0, g.length);
    const V3 q = sub(p, xyz(g.origin));
    const double x = dot(q, g.e1);
    const double y = dot(q, g.e2);
    const V3 normal{g.e1[1] * g.e2[2] - g.e1[2] * g.e2[1], g.e1[2] * g.e2[0] - g.e1[0] * g.e2[2],
                    g.e1[0] * g.e2[1] - g.e1[1] * g.e2[0]};
    const double z = dot(q, normal);
    const double sweep = g.k * g.length;
    double theta = std::atan2(y, x) - g.phi0;
    if (theta < 0.0) theta += 2.0 * kPi;
    if (theta <= sweep) return std::hypot(std::hypot(x, y) - g.radius, z);
    const V3 a = sub(p, xyz(positionAt(g, 0.0)));
    const V3 b = sub(p, xyz(positionAt(g, g.length)));
    return std::sqrt(std::min(dot(a, a), dot(b, b)));
}

}  // namespace

void PolylineSmoother::start(const AxisVector& first) {
    m_points.clear();
    m_points.push_back({first, 0.0});
    m_base = 0;
    m_knot = 0;
    m_tangentKnown = false;
    m_span = kSpanMm;
}

void PolylineSmoother::add(const AxisVector& vertex) {
    const Vertex& last = m_points.back();
    const V3 d = sub(xyz(vertex), xyz(last.position));
    m_points.push_back({vertex, last.s + std::sqrt(dot(d, d))});
}

double PolylineSmoother::pendingLength() const {
    return m_points.back().s - vertex(m_knot).s;
}

size_t PolylineSmoother::vertexBefore(double s) const {
    auto it = std::upper_bound(m_points.begin(), m_points.end(), s,
                               [](double value, const Vertex& v) { return value < v.s; });
    size_t offset = it == m_points.begin() ? 0 : static_cast<size_t>(it - m_points.begin()) - 1;
    return m_base + offset;
}

Vec3Array PolylineSmoother::pointAtLength(double s) const {
    s = std::clamp(s, m_points.front().s, m_points.back().s);
    size_t i = vertexBefore(s);
    const Vertex& a = vertex(i);
    if (i + 1 > segments()) return xyz(a.position);
    const Vertex& b = vertex(i + 1);
    double f = b.s > a.s ? (s - a.s) / (b.s - a.s) : 0.0;
    V3 p;
    for (size_t k = 0; k < 3; ++k)
        p[k] = a.position[k] + f * (b.position[k] - a.position[k]);
    return p;
}

Vec3Array PolylineSmoother::tangentAt(size_t index) const {
    const double s = vertex(index).s;
    const double before = s - m_points.front().s;
    const double after = m_points.back().s - s;
    const double central = std::min({before, after, 2.0 * kChordMm}) / 2.0;
    const double oneSided = std::min(kChordMm, std::max(before, after) / 2.0);
    if (central >= 0.5 * oneSided) {
        // Chords over +-h and +-2h: each is parallel to the tangent up to kappa' h^2 / 6 and
        // 4 kappa' h^2 / 6 (kappa' the rate of change of the curvature); their combination
        // 4/3 u1 - 1/3 u2 cancels that term.
        const double h = central;
        V3 u1 = unit(sub(pointAtLength(s + h), pointAtLength(s - h)));
        V3 u2 = unit(sub(pointAtLength(s + 2.0 * h), pointAtLength(s - 2.0 * h)));
        return combined(4.0 / 3.0, u1, -1.0 / 3.0, u2);
    }
    // At an end of the run: the chords to h and 2h turn by kappa h / 2 and kappa h from the
    // tangent; 2 u1 - u2 cancels that.
    const double h = oneSided;
    const V3 p = xyz(vertex(index).position);
    if (after >= before) {
        V3 u1 = unit(sub(pointAtLength(s + h), p));
        V3 u2 = unit(sub(pointAtLength(s + 2.0 * h), p));
        return combined(2.0, u1, -1.0, u2);
    }
    V3 u1 = unit(sub(p, pointAtLength(s - h)));
    V3 u2 = unit(sub(p, pointAtLength(s - 2.0 * h)));
    return combined(2.0, u1, -1.0, u2);
}

Vec3Array PolylineSmoother::knotAt(size_t index) const {
    const V3 p = xyz(vertex(index).position);
    const double s = vertex(index).s;
    const double h = std::min({kChordMm, s - m_points.front().s, m_points.back().s - s});
    if (index == m_base || index >= segments() || h <= 0.0) return p;
    // Each chord's direction is the tangent at its midpoint, and those are h apart: the
    // curvature vector is (after - before) / h, the sagitta of a segment l long is kappa l^2 / 8.
    const V3 before = unit(sub(p, pointAtLength(s - h)));
    const V3 after = unit(sub(pointAtLength(s + h), p));
    const double l = std::max(s - vertex(index - 1).s, vertex(index + 1).s - s);
    const double f = l * l / 16.0 / h;
    return {p[0] + f * (after[0] - before[0]), p[1] + f * (after[1] - before[1]),
            p[2] + f * (after[2] - before[2])};
}

double PolylineSmoother::deviationOf(const std::array<PathGeometry, 2>& arcs, size_t a, size_t b,
                                     double allowed) const {
    auto distance = [&](const V3& p) {
        return std::min(arcDistance(arcs[0], p), arcDistance(arcs[1], p));
    };
    double worst = 0.0;
    for (size_t k = a; k <= b && worst <= allowed; ++k) {
        const V3 p = xyz(vertex(k).position);
        worst = std::max(worst, distance(p));
        if (k == a) continue;
        const V3 q = xyz(vertex(k - 1).position);
        worst = std::max(worst,
                         distance({(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0, (p[2] + q[2]) / 2.0}));
    }
    return worst;
}

void PolylineSmoother::take(double deviation, bool final, std::vector<SmoothPiece>& out) {
    while (m_knot < segments()) {
        const double sKnot = vertex(m_knot).s;
        const double sEnd = m_points.back().s;
        // The knot at the span's end needs the chords 2h beyond it.
        if (!final && sEnd - sKnot < kSpanMm + 2.0 * kChordMm) break;
        size_t b = std::max(m_knot + 1, vertexBefore(sKnot + m_span));
        if (final && sEnd - sKnot <= 2.0 * m_span) {
            // Equal spans to the end of the run: no short span with a noisy tail is left.
            const double spans = std::ceil((sEnd - sKnot) / m_span);
            b = spans <= 1.0 ? segments()
                             : std::max(m_knot + 1, vertexBefore(sKnot + (sEnd - sKnot) / spans));
        }
        if (!m_tangentKnown) m_knotTangent = tangentAt(m_knot);
        const V3 p0 = m_tangentKnown ? m_knotPoint : xyz(vertex(m_knot).position);
        SmoothPiece piece;
        piece.firstSegment = m_knot + 1;
        piece.tangentToPrevious = m_tangentKnown;
        double allowed = deviation;
        while (true) {
            const V3 tb = tangentAt(b);
            const V3 pb = knotAt(b);
            int count = makeBiarc(vertex(m_knot).position, p0, m_knotTangent, pb, tb, piece.arcs);
            if (count == 2) piece.deviation = deviationOf(piece.arcs, m_knot, b, allowed);
            if (count == 2 && piece.deviation <= allowed) {
                piece.fitted = true;
                piece.lastSegment = b;
                piece.jointSegment =
                    std::clamp(vertexBefore(sKnot + piece.arcs[0].length) + 1, m_knot + 1, b);
                m_knotTangent = tb;
                m_knotPoint = pb;
                m_tangentKnown = true;
                break;
            }
            if (b == m_knot + 1 && allowed == deviation) {
                // One segment of a tight curve (the crest of a sine as 0.5 mm lines: sagitta
                // 0.012 mm) may take more: the filter's share is what the fit leaves.
                allowed = deviation * kLooseFitFactor;
                continue;
            }
            if (b == m_knot + 1) {
                piece.fitted = false;
                piece.startsOffVertex = m_tangentKnown;
                piece.lineStart = vertex(m_knot).position;
                for (size_t k = 0; k < 3; ++k)
                    piece.lineStart[k] = p0[k];
                piece.lastSegment = piece.jointSegment = b;
                piece.tangentToPrevious = false;
                m_tangentKnown = false;
                break;
            }
            b = std::clamp(vertexBefore(sKnot + (vertex(b).s - sKnot) / 2.0), m_knot + 1, b - 1);
        }
        // After a split, the next span starts from twice the length that fitted: a run that does
        // not describe a curve costs O(1) attempts per segment, not a halving from 2 mm each time.
        m_span = std::min(kSpanMm, 2.0 * (vertex(piece.lastSegment).s - sKnot));
        out.push_back(piece);
        m_knot = piece.lastSegment;
        // Keep the vertices the next knots' chords can reach back to.
        const double keepFrom = vertex(m_knot).s - 2.0 * kChordMm;
        while (m_base < m_knot && m_points[1].s <= keepFrom) {
            m_points.pop_front();
            ++m_base;
        }
    }
}

}  // namespace kerf::motion
