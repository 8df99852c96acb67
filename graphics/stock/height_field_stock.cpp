#include "graphics/stock/height_field_stock.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::graphics {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Interval of x on the row y where the point is within r of the segment a-b (2D), or empty.
bool capsuleRow(double ax, double ay, double bx, double by, double r, double y, double& lo,
                double& hi) {
    lo = kInf;
    hi = -kInf;
    auto disc = [&](double cx, double cy) {
        const double dy = y - cy;
        const double s = r * r - dy * dy;
        if (s < 0.0) return;
        const double w = std::sqrt(s);
        lo = std::min(lo, cx - w);
        hi = std::max(hi, cx + w);
    };
    disc(ax, ay);
    disc(bx, by);
    const double dx = bx - ax;
    const double dy = by - ay;
    const double len = std::hypot(dx, dy);
    if (len > 1e-12 && std::fabs(dy) > 1e-12 * len) {
        // Band: |cross(d, p - a)| <= r len and 0 <= dot(d, p - a) <= len^2, as x intervals.
        const double py = y - ay;
        // cross = dx * py - dy * px  ->  px in [(dx*py - r len)/dy, (dx*py + r len)/dy]
        double c0 = (dx * py - r * len) / dy;
        double c1 = (dx * py + r * len) / dy;
        if (c0 > c1) std::swap(c0, c1);
        // dot = dx * px + dy * py in [0, len^2]
        double t0 = dx != 0.0 ? (0.0 - dy * py) / dx : -kInf;
        double t1 = dx != 0.0 ? (len * len - dy * py) / dx : kInf;
        if (dx == 0.0) {
            const double dot = dy * py;
            if (dot < 0.0 || dot > len * len) {
                t0 = kInf;
                t1 = -kInf;
            }
        }
        if (t0 > t1) std::swap(t0, t1);
        const double b0 = std::max(c0, t0);
        const double b1 = std::min(c1, t1);
        if (b0 <= b1) {
            lo = std::min(lo, ax + b0);
            hi = std::max(hi, ax + b1);
        }
    } else if (len > 1e-12) {
        // Horizontal segment (in the grid's y): the band covers the rows within r.
        if (std::fabs(y - ay) <= r) {
            lo = std::min(lo, std::min(ax, bx));
            hi = std::max(hi, std::max(ax, bx));
        }
    }
    return lo <= hi;
}

// Lowest point of the swept cutter above (qx, qy) for a move a -> b, or +inf.
struct SweepEvaluator {
    const MillCutter& cutter;
    Vec3 a;
    Vec3 b;
    double r;
    double dx, dy, dz, len2;
    // Ball: sphere centres.
    Vec3 ca, cb, cd;
    double cdLen2;

    SweepEvaluator(const MillCutter& c, const Vec3& from, const Vec3& to)
        : cutter(c), a(from), b(to), r(c.radiusMm) {
        dx = b.x() - a.x();
        dy = b.y() - a.y();
        dz = b.z() - a.z();
        len2 = dx * dx + dy * dy;
        const double lift = cutter.kind == CutterKind::Ball ? r : 0.0;
        ca = a + Vec3(0, 0, lift);
        cb = b + Vec3(0, 0, lift);
        cd = cb - ca;
        cdLen2 = cd.squaredNorm();
    }

    double at(double qx, double qy) const {
        const double wx = qx - a.x();
        const double wy = qy - a.y();
        if (len2 < 1e-18) {
            const double rho = std::hypot(wx, wy);
            return rho <= r ? std::min(a.z(), b.z()) + cutter.heightAt(rho) : kInf;
        }
        if (std::fabs(dz) < 1e-12) {
            const double t = std::clamp((wx * dx + wy * dy) / len2, 0.0, 1.0);
            const double rho = std::hypot(wx - t * dx, wy - t * dy);
            return rho <= r ? a.z() + cutter.heightAt(rho) : kInf;
        }
        // Parameters where the axis is within r of the point: |w - t d|^2 <= r^2.
        const double bq = wx * dx + wy * dy;
        const double cq = wx * wx + wy * wy - r * r;
        const double disc = bq * bq - len2 * cq;
        if (disc < 0.0) return kInf;
        const double root = std::sqrt(disc);
        const double t1 = std::max(0.0, (bq - root) / len2);
        const double t2 = std::min(1.0, (bq + root) / len2);
        if (t1 > t2) return kInf;
        switch (cutter.kind) {
            case CutterKind::Flat:
                return a.z() + dz * (dz > 0.0 ? t1 : t2);
            case CutterKind::Ball:
                return ball(qx, qy);
            default:
                break;
        }
        // Convex in t: golden-section search over [t1, t2].
        auto f = [&](double t) {
            return a.z() + dz * t + cutter.heightAt(std::hypot(wx - t * dx, wy - t * dy));
        };
        double lo = t1;
        double hi = t2;
        constexpr double kG = 0.6180339887498949;
        double m1 = hi - kG * (hi - lo);
        double m2 = lo + kG * (hi - lo);
        double f1 = f(m1);
        double f2 = f(m2);
        for (int i = 0; i < 28 && hi - lo > 1e-7; ++i) {
            if (f1 <= f2) {
                hi = m2;
                m2 = m1;
                f2 = f1;
                m1 = hi - kG * (hi - lo);
                f1 = f(m1);
            } else {
                lo = m1;
                m1 = m2;
                f1 = f2;
                m2 = lo + kG * (hi - lo);
                f2 = f(m2);
            }
        }
        return std::min({f(t1), f(t2), f1, f2});
    }

    // Ball end mill: the lowest entry of a vertical line into the capsule of sphere centres.
    double ball(double qx, double qy) const {
        double best = kInf;
        auto sphere = [&](const Vec3& c) {
            const double rho2 = (qx - c.x()) * (qx - c.x()) + (qy - c.y()) * (qy - c.y());
            if (rho2 <= r * r) best = std::min(best, c.z() - std::sqrt(r * r - rho2));
        };
        sphere(ca);
        sphere(cb);
        const double horizontal = 1.0 - cd.z() * cd.z() / cdLen2;
        if (cdLen2 > 1e-18 && horizontal > 1e-12) {
            const Vec3 w0(qx - ca.x(), qy - ca.y(), 0.0);
            const double k = w0.dot(cd);
            // |w0|^2 + z^2 - (k + z cdz)^2 / L2 = r^2, z relative to ca.z
            const double qa = horizontal;
            const double qb = -2.0 * k * cd.z() / cdLen2;
            const double qc = w0.squaredNorm() - k * k / cdLen2 - r * r;
            const double disc = qb * qb - 4.0 * qa * qc;
            if (disc >= 0.0) {
                const double z = (-qb - std::sqrt(disc)) / (2.0 * qa);
                const double t = (k + z * cd.z()) / cdLen2;
                if (t >= 0.0 && t <= 1.0) best = std::min(best, ca.z() + z);
            }
        }
        return best;
    }
};

}  // namespace

HeightFieldStock::HeightFieldStock(const Vec3& min, const Vec3& max, double cellMm,
                                   size_t maxCells) {
    const Vec3 lo = min.cwiseMin(max);
    const Vec3 hi = min.cwiseMax(max);
    allocate(lo.x(), lo.y(), hi.x(), hi.y(), cellMm, maxCells);
    m_bottom = lo.z();
    m_topZ = hi.z();
    std::fill(m_top.begin(), m_top.end(), static_cast<float>(m_topZ));
    m_initialVolume = volumeMm3();
}

HeightFieldStock HeightFieldStock::cylinder(double cx, double cy, double radius, double inner,
                                            double zMin, double zMax, double cellMm,
                                            size_t maxCells) {
    HeightFieldStock stock;
    radius = std::fabs(radius);
    stock.allocate(cx - radius, cy - radius, cx + radius, cy + radius, cellMm, maxCells);
    stock.m_bottom = std::min(zMin, zMax);
    stock.m_topZ = std::max(zMin, zMax);
    for (int j = 0; j < stock.m_ny; ++j) {
        for (int i = 0; i < stock.m_nx; ++i) {
            const double x = stock.m_x0 + (i + 0.5) * stock.m_cell - cx;
            const double y = stock.m_y0 + (j + 0.5) * stock.m_cell - cy;
            const double rho = std::hypot(x, y);
            const bool material = rho <= radius && rho >= std::fabs(inner);
            stock.m_top[stock.index(i, j)] =
                static_cast<float>(material ? stock.m_topZ : stock.m_bottom);
        }
    }
    stock.m_initialVolume = stock.volumeMm3();
    return stock;
}

void HeightFieldStock::allocate(double x0, double y0, double x1, double y1, double cellMm,
                                size_t maxCells) {
    double cell = std::isfinite(cellMm) && cellMm > 0.0 ? cellMm : 0.1;
    const double w = std::isfinite(x1 - x0) ? std::max(x1 - x0, 0.0) : 0.0;
    const double h = std::isfinite(y1 - y0) ? std::max(y1 - y0, 0.0) : 0.0;
    maxCells = std::max<size_t>(maxCells, 1);
    // Coarsen until the grid fits (also guards against absurd blanks).
    while ((std::ceil(w / cell) + 1.0) * (std::ceil(h / cell) + 1.0) >
           static_cast<double>(maxCells)) {
        cell *= 1.25;
    }
    m_cell = cell;
    m_nx = std::max(1, static_cast<int>(std::ceil(w / cell - 1e-9)));
    m_ny = std::max(1, static_cast<int>(std::ceil(h / cell - 1e-9)));
    // Centre the grid on the blank so the cells cover it symmetrically.
    m_x0 = std::isfinite(x0) ? (x0 + x1) * 0.5 - m_nx * cell * 0.5 : 0.0;
    m_y0 = std::isfinite(y0) ? (y0 + y1) * 0.5 - m_ny * cell * 0.5 : 0.0;
    m_top.assign(static_cast<size_t>(m_nx) * static_cast<size_t>(m_ny), 0.0f);
}

double HeightFieldStock::volumeMm3() const {
    double sum = 0.0;
    for (float top : m_top)
        sum += std::max(0.0, double{top} - m_bottom);
    return sum * m_cell * m_cell;
}

bool HeightFieldStock::cut(const Vec3& a, const Vec3& b, const MillCutter& cutter) {
    if (!cutter.cuts() || m_top.empty()) return false;
    if (!a.allFinite() || !b.allFinite()) return false;
    if (std::min(a.z(), b.z()) >= m_topZ) return false;  // above the blank: nothing to cut
    const double r = cutter.radiusMm;
    const double xmin = std::min(a.x(), b.x()) - r;
    const double xmax = std::max(a.x(), b.x()) + r;
    const double ymin = std::min(a.y(), b.y()) - r;
    const double ymax = std::max(a.y(), b.y()) + r;
    const double fj0 = std::floor((ymin - m_y0) / m_cell - 0.5);
    const double fj1 = std::ceil((ymax - m_y0) / m_cell - 0.5);
    if (fj1 < 0.0 || fj0 >= m_ny) return false;
    const double fi0 = std::floor((xmin - m_x0) / m_cell - 0.5);
    const double fi1 = std::ceil((xmax - m_x0) / m_cell - 0.5);
    if (fi1 < 0.0 || fi0 >= m_nx) return false;
    const int j0 = static_cast<int>(std::max(0.0, fj0));
    const int j1 = static_cast<int>(std::min<double>(m_ny - 1, fj1));
    SweepEvaluator sweep(cutter, a, b);
    // No point of the tool is below the lower tip: cells already there cannot change (repeated
    // passes skip most of their cells this way).
    const auto lowest = static_cast<float>(std::min(a.z(), b.z()));
    bool removed = false;
    for (int j = j0; j <= j1; ++j) {
        const double y = m_y0 + (j + 0.5) * m_cell;
        double lo = 0.0;
        double hi = 0.0;
        if (!capsuleRow(a.x(), a.y(), b.x(), b.y(), r, y, lo, hi)) continue;
        const double ci0 = std::ceil((lo - m_x0) / m_cell - 0.5);
        const double ci1 = std::floor((hi - m_x0) / m_cell - 0.5);
        const int i0 = static_cast<int>(std::max(0.0, ci0));
        const int i1 = static_cast<int>(std::min<double>(m_nx - 1, ci1));
        float* row = &m_top[index(0, j)];
        for (int i = i0; i <= i1; ++i) {
            if (double{row[i]} <= m_bottom || row[i] <= lowest) continue;
            const double x = m_x0 + (i + 0.5) * m_cell;
            const auto z = static_cast<float>(std::max(sweep.at(x, y), m_bottom));
            if (z < row[i]) {
                row[i] = z;
                removed = true;
            }
        }
    }
    return removed;
}

Mesh HeightFieldStock::mesh(int maxSide) const {
    Mesh mesh;
    if (m_top.empty()) return mesh;
    const int side = std::max(2, maxSide);
    const int step = std::max(1, (std::max(m_nx, m_ny) + side - 1) / side);
    const int vx = (m_nx + step - 1) / step;  // samples per side
    const int vy = (m_ny + step - 1) / step;
    std::vector<float> h(static_cast<size_t>(vx) * static_cast<size_t>(vy));
    for (int J = 0; J < vy; ++J) {
        for (int I = 0; I < vx; ++I) {
            float lowest = std::numeric_limits<float>::max();
            for (int j = J * step; j < std::min(m_ny, (J + 1) * step); ++j) {
                for (int i = I * step; i < std::min(m_nx, (I + 1) * step); ++i) {
                    lowest = std::min(lowest, m_top[index(i, j)]);
                }
            }
            h[static_cast<size_t>(J) * static_cast<size_t>(vx) + static_cast<size_t>(I)] = lowest;
        }
    }
    const double span = m_cell * step;
    const double bottom = m_bottom;
    auto H = [&](int I, int J) {
        I = std::clamp(I, 0, vx - 1);
        J = std::clamp(J, 0, vy - 1);
        return double{h[static_cast<size_t>(J) * static_cast<size_t>(vx) + static_cast<size_t>(I)]};
    };
    // Sample positions: block centres, the outermost ones moved onto the blank's edges.
    auto X = [&](int I) {
        if (I == 0) return m_x0;
        if (I == vx - 1) return m_x0 + m_nx * m_cell;
        return m_x0 + (I + 0.5) * span;
    };
    auto Y = [&](int J) {
        if (J == 0) return m_y0;
        if (J == vy - 1) return m_y0 + m_ny * m_cell;
        return m_y0 + (J + 0.5) * span;
    };
    std::vector<uint32_t> top(static_cast<size_t>(vx) * static_cast<size_t>(vy));
    for (int J = 0; J < vy; ++J) {
        for (int I = 0; I < vx; ++I) {
            const double gx = (H(I + 1, J) - H(I - 1, J)) / (2.0 * span);
            const double gy = (H(I, J + 1) - H(I, J - 1)) / (2.0 * span);
            top[static_cast<size_t>(J) * static_cast<size_t>(vx) + static_cast<size_t>(I)] =
                mesh.addVertex(Vec3(X(I), Y(J), H(I, J)), Vec3(-gx, -gy, 1.0).normalized());
        }
    }
    auto T = [&](int I, int J) {
        return top[static_cast<size_t>(J) * static_cast<size_t>(vx) + static_cast<size_t>(I)];
    };
    for (int J = 0; J + 1 < vy; ++J) {
        for (int I = 0; I + 1 < vx; ++I) {
            const bool empty = H(I, J) <= bottom && H(I + 1, J) <= bottom &&
                               H(I, J + 1) <= bottom && H(I + 1, J + 1) <= bottom;
            if (!empty) mesh.addQuad(T(I, J), T(I + 1, J), T(I + 1, J + 1), T(I, J + 1));
        }
    }
    // Walls along the four edges and the bottom.
    auto wall = [&](int count, auto position, auto height, const Vec3& normal, bool flip) {
        for (int k = 0; k + 1 < count; ++k) {
            const Vec3 p0 = position(k);
            const Vec3 p1 = position(k + 1);
            const double h0 = height(k);
            const double h1 = height(k + 1);
            if (h0 <= bottom && h1 <= bottom) continue;
            const uint32_t a = mesh.addVertex(Vec3(p0.x(), p0.y(), bottom), normal);
            const uint32_t b = mesh.addVertex(Vec3(p1.x(), p1.y(), bottom), normal);
            const uint32_t c = mesh.addVertex(Vec3(p1.x(), p1.y(), h1), normal);
            const uint32_t d = mesh.addVertex(Vec3(p0.x(), p0.y(), h0), normal);
            if (flip) {
                mesh.addQuad(a, d, c, b);
            } else {
                mesh.addQuad(a, b, c, d);
            }
        }
    };
    wall(
        vx, [&](int k) { return Vec3(X(k), Y(0), 0); }, [&](int k) { return H(k, 0); },
        Vec3(0, -1, 0), false);
    wall(
        vx, [&](int k) { return Vec3(X(k), Y(vy - 1), 0); }, [&](int k) { return H(k, vy - 1); },
        Vec3(0, 1, 0), true);
    wall(
        vy, [&](int k) { return Vec3(X(0), Y(k), 0); }, [&](int k) { return H(0, k); },
        Vec3(-1, 0, 0), true);
    wall(
        vy, [&](int k) { return Vec3(X(vx - 1), Y(k), 0); }, [&](int k) { return H(vx - 1, k); },
        Vec3(1, 0, 0), false);
    const Vec3 down(0, 0, -1);
    const uint32_t b0 = mesh.addVertex(Vec3(X(0), Y(0), bottom), down);
    const uint32_t b1 = mesh.addVertex(Vec3(X(vx - 1), Y(0), bottom), down);
    const uint32_t b2 = mesh.addVertex(Vec3(X(vx - 1), Y(vy - 1), bottom), down);
    const uint32_t b3 = mesh.addVertex(Vec3(X(0), Y(vy - 1), bottom), down);
    mesh.addQuad(b0, b3, b2, b1);
    return mesh;
}

}  // namespace kerf::graphics
