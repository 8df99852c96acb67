#include "motion/path/path_geometry.h"

#include <algorithm>
#include <cmath>

namespace kerf::motion {

namespace {

double dot3(const Vec3Array& a, const Vec3Array& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double xyzLength(const AxisVector& d) {
    return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

double otherLength(const AxisVector& d) {
    double sum = 0.0;
    for (size_t i = 3; i < d.size(); ++i)
        sum += d[i] * d[i];
    return std::sqrt(sum);
}

}  // namespace

AxisVector positionAt(const PathGeometry& g, double s) noexcept {
    AxisVector p;
    for (size_t i = 0; i < p.size(); ++i)
        p[i] = g.origin[i] + g.rate[i] * s;
    if (g.radius > 0.0) {
        double phi = g.phi0 + g.k * s;
        double c = std::cos(phi) * g.radius;
        double sn = std::sin(phi) * g.radius;
        for (size_t i = 0; i < 3; ++i)
            p[i] += c * g.e1[i] + sn * g.e2[i];
    }
    return p;
}

PathPoint pointAt(const PathGeometry& g, double s) noexcept {
    PathPoint out;
    for (size_t i = 0; i < out.position.size(); ++i) {
        out.position[i] = g.origin[i] + g.rate[i] * s;
        out.tangent[i] = g.rate[i];
    }
    if (g.radius > 0.0) {
        double phi = g.phi0 + g.k * s;
        double c = std::cos(phi);
        double sn = std::sin(phi);
        double rk = g.radius * g.k;
        double rkk = rk * g.k;
        for (size_t i = 0; i < 3; ++i) {
            out.position[i] += g.radius * (c * g.e1[i] + sn * g.e2[i]);
            out.tangent[i] += rk * (-sn * g.e1[i] + c * g.e2[i]);
            out.curvature[i] = -rkk * (c * g.e1[i] + sn * g.e2[i]);
        }
    }
    return out;
}

PathGeometry makeLine(const AxisVector& from, const AxisVector& to) noexcept {
    PathGeometry g;
    AxisVector d;
    for (size_t i = 0; i < d.size(); ++i)
        d[i] = to[i] - from[i];
    double length = xyzLength(d);
    if (length < 1e-9) length = otherLength(d);
    g.length = length;
    g.origin = from;
    if (length > 0.0) {
        for (size_t i = 0; i < d.size(); ++i)
            g.rate[i] = d[i] / length;
    }
    return g;
}

PathGeometry makeHelix(const AxisVector& from, const AxisVector& to, const Vec3Array& center,
                       Axis first, Axis second, Axis normal, double sweepRad) noexcept {
    const size_t f = static_cast<size_t>(axisIndex(first));
    const size_t sc = static_cast<size_t>(axisIndex(second));
    const size_t n = static_cast<size_t>(axisIndex(normal));
    double rx = from[f] - center[f];
    double ry = from[sc] - center[sc];
    double radius = std::hypot(rx, ry);
    double rise = to[n] - from[n];
    double planar = radius * std::fabs(sweepRad);
    PathGeometry g;
    g.length = std::hypot(planar, rise);
    if (radius < 1e-12 || g.length < 1e-12) return makeLine(from, to);
    g.radius = radius;
    g.k = std::fabs(sweepRad) / g.length;
    double turn = sweepRad >= 0.0 ? 1.0 : -1.0;
    g.e1 = {0.0, 0.0, 0.0};
    g.e2 = {0.0, 0.0, 0.0};
    g.e1[f] = rx / radius;
    g.e1[sc] = ry / radius;
    // e2 = turn * (normal x e1) in the plane's right-handed frame.
    g.e2[f] = -turn * ry / radius;
    g.e2[sc] = turn * rx / radius;
    for (size_t i = 0; i < g.origin.size(); ++i) {
        g.origin[i] = from[i];
        g.rate[i] = (to[i] - from[i]) / g.length;
    }
    // The circle part carries the in-plane motion: the linear part keeps only the centre.
    g.origin[f] = center[f];
    g.origin[sc] = center[sc];
    g.rate[f] = 0.0;
    g.rate[sc] = 0.0;
    return g;
}

PathGeometry makeTangentArc(const AxisVector& from, const Vec3Array& tangent,
                            const AxisVector& to) noexcept {
    Vec3Array w{to[0] - from[0], to[1] - from[1], to[2] - from[2]};
    double along = dot3(w, tangent);
    Vec3Array perp{w[0] - along * tangent[0], w[1] - along * tangent[1], w[2] - along * tangent[2]};
    double h = std::sqrt(dot3(perp, perp));
    double chordSq = dot3(w, w);
    if (h <= 1e-12 * std::max(1.0, std::sqrt(chordSq))) {
        AxisVector end = from;
        for (size_t i = 0; i < 3; ++i)
            end[i] = to[i];
        return makeLine(from, end);
    }
    PathGeometry g;
    Vec3Array normal{perp[0] / h, perp[1] / h, perp[2] / h};
    g.radius = chordSq / (2.0 * h);
    double sweep = 2.0 * std::atan2(h, along);
    g.length = g.radius * sweep;
    g.k = 1.0 / g.radius;
    g.origin = from;
    for (size_t i = 0; i < 3; ++i) {
        g.origin[i] = from[i] + g.radius * normal[i];
        g.e1[i] = -normal[i];
        g.e2[i] = tangent[i];
    }
    return g;
}

PathGeometry trimmed(const PathGeometry& g, double s0, double s1) noexcept {
    PathGeometry t = g;
    t.length = std::max(0.0, s1 - s0);
    for (size_t i = 0; i < t.origin.size(); ++i)
        t.origin[i] = g.origin[i] + g.rate[i] * s0;
    t.phi0 = g.phi0 + g.k * s0;
    return t;
}

double distanceTo(const PathGeometry& g, const Vec3Array& p, double s0, double s1) noexcept {
    auto dist = [&](double s) {
        AxisVector q = positionAt(g, s);
        return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                         (p[2] - q[2]) * (p[2] - q[2]));
    };
    if (!g.curved()) {
        AxisVector a = positionAt(g, s0);
        Vec3Array d{g.rate[0], g.rate[1], g.rate[2]};
        double len2 = dot3(d, d);
        if (len2 <= 0.0) return dist(s0);
        double t = ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / len2;
        return dist(s0 + std::clamp(t, 0.0, s1 - s0));
    }
    // Candidates: both ends and every turn's point at the planar angle of p (the nearest point
    // of a circle; a helix's rise moves it slightly), each refined by Newton steps on
    // (q(s) - p) . q'(s) = 0. Every candidate's distance is exact, so the result never
    // underestimates.
    auto refined = [&](double s) {
        for (int i = 0; i < 4; ++i) {
            PathPoint q = pointAt(g, s);
            double slope = 0.0;
            double curve = 0.0;
            for (size_t a = 0; a < 3; ++a) {
                const double d = q.position[a] - p[a];
                slope += d * q.tangent[a];
                curve += q.tangent[a] * q.tangent[a] + d * q.curvature[a];
            }
            if (curve <= 0.0) break;
            const double next = std::clamp(s - slope / curve, s0, s1);
            if (next == s) break;
            s = next;
        }
        return dist(s);
    };
    double best = std::min(dist(s0), dist(s1));
    const Vec3Array d{p[0] - g.origin[0], p[1] - g.origin[1], p[2] - g.origin[2]};
    const double theta = std::atan2(dot3(d, g.e2), dot3(d, g.e1));
    constexpr double kTurn = 6.283185307179586476925;
    const double firstTurn = std::ceil((g.phi0 + g.k * s0 - theta) / kTurn);
    const double lastTurn = std::floor((g.phi0 + g.k * s1 - theta) / kTurn);
    for (double m = firstTurn; m <= lastTurn && m < firstTurn + 64.0; m += 1.0)
        best = std::min(best, refined((theta + kTurn * m - g.phi0) / g.k));
    best = std::min({best, refined(s0), refined(s1)});
    return best;
}

CosRange cosRange(double from, double to, double psi) noexcept {
    constexpr double kTwoPiLocal = 6.283185307179586476925;
    double a = std::cos(from - psi);
    double b = std::cos(to - psi);
    CosRange r{std::min(a, b), std::max(a, b)};
    // Peaks of cos at psi + n 2pi (1) and psi + pi + n 2pi (-1).
    double firstMax = psi + std::ceil((from - psi) / kTwoPiLocal) * kTwoPiLocal;
    if (firstMax <= to) r.hi = 1.0;
    double firstMin = psi + kTwoPiLocal / 2.0 +
                      std::ceil((from - psi - kTwoPiLocal / 2.0) / kTwoPiLocal) * kTwoPiLocal;
    if (firstMin <= to) r.lo = -1.0;
    return r;
}

AxisBounds axisBounds(const PathGeometry& g) noexcept {
    AxisBounds b;
    for (size_t i = 0; i < g.rate.size(); ++i)
        b.tangent[i] = std::fabs(g.rate[i]);
    if (g.radius > 0.0) {
        for (size_t i = 0; i < 3; ++i) {
            double amp = std::hypot(g.e1[i], g.e2[i]) * g.radius;
            b.tangent[i] += amp * g.k;
            b.curvature[i] = amp * g.k * g.k;
            b.curvatureRate[i] = amp * g.k * g.k * g.k;
        }
    }
    return b;
}

}  // namespace kerf::motion
