#include "graphics/stock/voxel_stock.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace kerf::graphics {

namespace {

// Whether a point lies in the volume a cutter (a solid of revolution about the unit axis u, tip
// at its lowest point, `length` long) sweeps while its tip moves from a along d. With q the point
// relative to the tip at time t: its height above the tip h(t) is linear in t and its squared
// distance from the axis rho(t)^2 a convex quadratic, so each bound on them holds on one interval
// of t; the surface height of the profile is convex and non-decreasing in rho for every cutter
// kind, which makes h(t) - heightAt(rho(t)) concave on that interval: its maximum decides.
class SweptCutter {
public:
    SweptCutter(const Vec3& a, const Vec3& d, const Vec3& u, const MillCutter& cutter,
                double radius, double length)
        : m_a(a), m_u(u), m_cutter(cutter), m_radius(radius), m_length(length) {
        m_hd = u.dot(d);
        m_rd = d - m_hd * u;
        m_rdSquared = m_rd.squaredNorm();
        m_flat = cutter.kind == CutterKind::Flat || cutter.profileHeight() <= 0.0;
    }

    bool contains(const Vec3& p) const {
        const Vec3 q0 = p - m_a;
        const double h0 = m_u.dot(q0);
        const Vec3 r0 = q0 - h0 * m_u;
        // rho(t)^2 = |r0|^2 - 2 t r0.rd + t^2 |rd|^2 <= R^2
        double lo = 0.0;
        double hi = 1.0;
        const double c = r0.squaredNorm() - m_radius * m_radius;
        const double b = r0.dot(m_rd);
        if (m_rdSquared < 1e-18) {
            if (c > 0.0) return false;
        } else {
            const double disc = b * b - m_rdSquared * c;
            if (disc < 0.0) return false;
            const double s = std::sqrt(disc);
            lo = std::max(lo, (b - s) / m_rdSquared);
            hi = std::min(hi, (b + s) / m_rdSquared);
        }
        // 0 <= h(t) = h0 - t hd <= length
        if (!clampLinear(h0, -m_hd, 0.0, m_length, lo, hi)) return false;
        if (m_flat) return true;
        auto g = [&](double t) {
            const double rho = std::min(m_radius, (r0 - t * m_rd).norm());
            return h0 - t * m_hd - m_cutter.heightAt(rho);
        };
        if (g(lo) >= 0.0 || g(hi) >= 0.0) return true;
        // Upper bound of the maximum: the highest h against the profile at the nearest approach
        // to the axis; most points below the tool end here.
        const double nearest = m_rdSquared < 1e-18 ? lo : std::clamp(b / m_rdSquared, lo, hi);
        const double hMax = std::max(h0 - lo * m_hd, h0 - hi * m_hd);
        if (hMax < m_cutter.heightAt(std::min(m_radius, (r0 - nearest * m_rd).norm())))
            return false;
        for (int i = 0; i < 30 && hi - lo > 1e-9; ++i) {
            const double m1 = lo + (hi - lo) / 3.0;
            const double m2 = hi - (hi - lo) / 3.0;
            const double g1 = g(m1);
            const double g2 = g(m2);
            if (g1 >= 0.0 || g2 >= 0.0) return true;
            if (g1 < g2) {
                lo = m1;
            } else {
                hi = m2;
            }
        }
        return false;
    }

private:
    // Narrows [lo, hi] to the t where min <= v0 + t slope <= max; false when nothing is left.
    static bool clampLinear(double v0, double slope, double min, double max, double& lo,
                            double& hi) {
        if (std::abs(slope) < 1e-15) {
            if (v0 < min || v0 > max) return false;
        } else {
            double t0 = (min - v0) / slope;
            double t1 = (max - v0) / slope;
            if (t0 > t1) std::swap(t0, t1);
            lo = std::max(lo, t0);
            hi = std::min(hi, t1);
        }
        return lo <= hi;
    }

    Vec3 m_a;
    Vec3 m_u;
    const MillCutter& m_cutter;
    double m_radius;
    double m_length;
    double m_hd = 0.0;
    Vec3 m_rd;
    double m_rdSquared = 0.0;
    bool m_flat = true;
};

}  // namespace

VoxelStock::VoxelStock(const Vec3& min, const Vec3& max, double cellMm, size_t maxVoxels) {
    allocate(min, max, cellMm, maxVoxels);
    std::fill(m_bits.begin(), m_bits.end(), ~uint64_t{0});
    // Bits past the end of each row stay clear, so counts need no mask.
    const int tail = m_nx & 63;
    if (tail != 0) {
        for (size_t r = m_wordsPerRow - 1; r < m_bits.size(); r += m_wordsPerRow)
            m_bits[r] = (uint64_t{1} << tail) - 1;
    }
}

void VoxelStock::allocate(const Vec3& min, const Vec3& max, double cellMm, size_t maxVoxels) {
    const Vec3 size = (max - min).cwiseMax(1e-6);
    double cell = std::max(cellMm, 1e-3);
    const double budget = static_cast<double>(std::max<size_t>(maxVoxels, 1));
    const double wanted = size.prod() / (cell * cell * cell);
    if (wanted > budget) cell *= std::cbrt(wanted / budget) * 1.0001;
    m_cell = cell;
    m_origin = min;
    m_nx = std::max(1, static_cast<int>(std::ceil(size.x() / cell - 1e-9)));
    m_ny = std::max(1, static_cast<int>(std::ceil(size.y() / cell - 1e-9)));
    m_nz = std::max(1, static_cast<int>(std::ceil(size.z() / cell - 1e-9)));
    m_wordsPerRow = static_cast<size_t>((m_nx + 63) / 64);
    m_bits.assign(m_wordsPerRow * static_cast<size_t>(m_ny) * static_cast<size_t>(m_nz), 0);
}

VoxelStock VoxelStock::fromHeightField(const HeightFieldStock& field, size_t maxVoxels) {
    VoxelStock stock;
    stock.allocate(field.minCorner(), field.maxCorner(), field.cellMm(), maxVoxels);
    const double fieldCell = field.cellMm();
    for (int k = 0; k < stock.m_nz; ++k) {
        const double z = stock.m_origin.z() + (k + 0.5) * stock.m_cell;
        for (int j = 0; j < stock.m_ny; ++j) {
            const double y = stock.m_origin.y() + (j + 0.5) * stock.m_cell;
            const int fj = std::clamp(static_cast<int>((y - field.minCorner().y()) / fieldCell), 0,
                                      field.cellsY() - 1);
            uint64_t* words = &stock.m_bits[stock.row(j, k)];
            for (int i = 0; i < stock.m_nx; ++i) {
                const double x = stock.m_origin.x() + (i + 0.5) * stock.m_cell;
                const int fi = std::clamp(static_cast<int>((x - field.minCorner().x()) / fieldCell),
                                          0, field.cellsX() - 1);
                if (field.hasMaterial(fi, fj) && z < field.topAt(fi, fj))
                    words[i >> 6] |= uint64_t{1} << (i & 63);
            }
        }
    }
    return stock;
}

VoxelStock VoxelStock::cylinder(int along, double radiusMm, double innerRadiusMm, double lowMm,
                                double highMm, double cellMm, size_t maxVoxels) {
    VoxelStock stock;
    Vec3 min = Vec3::Constant(-radiusMm);
    Vec3 max = Vec3::Constant(radiusMm);
    min[along] = lowMm;
    max[along] = highMm;
    stock.allocate(min, max, cellMm, maxVoxels);
    const int u = (along + 1) % 3;
    const int v = (along + 2) % 3;
    const double outer = radiusMm * radiusMm;
    const double inner = innerRadiusMm * innerRadiusMm;
    for (int k = 0; k < stock.m_nz; ++k) {
        for (int j = 0; j < stock.m_ny; ++j) {
            uint64_t* words = &stock.m_bits[stock.row(j, k)];
            for (int i = 0; i < stock.m_nx; ++i) {
                const Vec3 centre = stock.m_origin + stock.m_cell * Vec3(i + 0.5, j + 0.5, k + 0.5);
                const double r2 = centre[u] * centre[u] + centre[v] * centre[v];
                if (r2 <= outer && r2 >= inner && centre[along] <= highMm)
                    words[i >> 6] |= uint64_t{1} << (i & 63);
            }
        }
    }
    return stock;
}

double VoxelStock::cuttingLengthMm(const MillCutter& cutter) {
    // Long enough for the shank to clear what a deep plunge leaves above the flutes.
    return std::max({cutter.lengthMm, 10.0 * cutter.radiusMm, 30.0});
}

bool VoxelStock::cut(const Vec3& a, const Vec3& b, const Vec3& axis, const MillCutter& cutter) {
    if (m_bits.empty() || !a.allFinite() || !b.allFinite() || !axis.allFinite()) return false;
    const double norm = axis.norm();
    if (norm < 1e-12) return false;
    const Vec3 u = axis / norm;
    // A sharp tool still cuts one voxel wide.
    const double radius = std::max(cutter.radiusMm, m_cell * 0.5);
    const double length = cuttingLengthMm(cutter);
    const SweptCutter swept(a, b - a, u, cutter, radius, length);
    Vec3 lo = a.cwiseMin(b).cwiseMin(a + length * u).cwiseMin(b + length * u);
    Vec3 hi = a.cwiseMax(b).cwiseMax(a + length * u).cwiseMax(b + length * u);
    // A disc of radius R about u reaches R sqrt(1 - u_i^2) along axis i: a tool along Z does not
    // reach below its tip.
    const Vec3 reach = radius * (Vec3::Ones() - u.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
    lo -= reach;
    hi += reach;
    auto first = [&](double v, double origin) {
        return static_cast<int>(std::floor((v - origin) / m_cell - 0.5)) + 1;
    };
    auto last = [&](double v, double origin) {
        return static_cast<int>(std::floor((v - origin) / m_cell - 0.5));
    };
    const int i0 = std::max(0, first(lo.x(), m_origin.x()));
    const int i1 = std::min(m_nx - 1, last(hi.x(), m_origin.x()));
    const int j0 = std::max(0, first(lo.y(), m_origin.y()));
    const int j1 = std::min(m_ny - 1, last(hi.y(), m_origin.y()));
    const int k0 = std::max(0, first(lo.z(), m_origin.z()));
    const int k1 = std::min(m_nz - 1, last(hi.z(), m_origin.z()));
    bool removed = false;
    for (int k = k0; k <= k1; ++k) {
        const double z = m_origin.z() + (k + 0.5) * m_cell;
        for (int j = j0; j <= j1; ++j) {
            const double y = m_origin.y() + (j + 0.5) * m_cell;
            uint64_t* words = &m_bits[row(j, k)];
            for (int i = i0; i <= i1; ++i) {
                uint64_t& word = words[i >> 6];
                if (word == 0) {
                    i |= 63;  // the rest of this word is air
                    continue;
                }
                const uint64_t mask = uint64_t{1} << (i & 63);
                if ((word & mask) == 0) continue;
                const Vec3 p(m_origin.x() + (i + 0.5) * m_cell, y, z);
                if (swept.contains(p)) {
                    word &= ~mask;
                    removed = true;
                }
            }
        }
    }
    return removed;
}

bool VoxelStock::solidAt(const Vec3& p) const {
    const Vec3 f = (p - m_origin) / m_cell;
    if (!f.allFinite() || f.minCoeff() < 0.0) return false;
    const int i = static_cast<int>(f.x());
    const int j = static_cast<int>(f.y());
    const int k = static_cast<int>(f.z());
    if (i >= m_nx || j >= m_ny || k >= m_nz) return false;
    return bit(i, j, k);
}

size_t VoxelStock::solidVoxels() const {
    size_t count = 0;
    for (uint64_t word : m_bits)
        count += static_cast<size_t>(std::popcount(word));
    return count;
}

double VoxelStock::volumeMm3() const {
    return static_cast<double>(solidVoxels()) * m_cell * m_cell * m_cell;
}

int VoxelStock::countRow(int j, int k, int i0, int i1) const {
    const uint64_t* words = &m_bits[row(j, k)];
    int count = 0;
    for (int i = i0; i < i1;) {
        const int bitIndex = i & 63;
        const int span = std::min(64 - bitIndex, i1 - i);
        const uint64_t mask = span == 64 ? ~uint64_t{0} : ((uint64_t{1} << span) - 1) << bitIndex;
        count += std::popcount(words[i >> 6] & mask);
        i += span;
    }
    return count;
}

Mesh VoxelStock::mesh(int maxSide) const {
    Mesh mesh;
    if (m_bits.empty()) return mesh;
    const int side = std::max(2, maxSide);
    const int step = std::max(1, (std::max({m_nx, m_ny, m_nz}) + side - 1) / side);
    const int cx = (m_nx + step - 1) / step;
    const int cy = (m_ny + step - 1) / step;
    const int cz = (m_nz + step - 1) / step;
    auto at = [&](int I, int J, int K) {
        return (static_cast<size_t>(K) * static_cast<size_t>(cy) + static_cast<size_t>(J)) *
                   static_cast<size_t>(cx) +
               static_cast<size_t>(I);
    };
    std::vector<uint8_t> solid(static_cast<size_t>(cx) * static_cast<size_t>(cy) *
                               static_cast<size_t>(cz));
    for (int K = 0; K < cz; ++K) {
        for (int J = 0; J < cy; ++J) {
            for (int I = 0; I < cx; ++I) {
                const int i0 = I * step;
                const int i1 = std::min(m_nx, i0 + step);
                int count = 0;
                int total = 0;
                for (int k = K * step; k < std::min(m_nz, (K + 1) * step); ++k) {
                    for (int j = J * step; j < std::min(m_ny, (J + 1) * step); ++j) {
                        count += countRow(j, k, i0, i1);
                        total += i1 - i0;
                    }
                }
                solid[at(I, J, K)] = 2 * count >= total && count > 0;
            }
        }
    }
    const double span = m_cell * step;
    auto corner = [&](int I, int J, int K) {
        return Vec3(m_origin.x() + std::min(I * span, m_nx * m_cell),
                    m_origin.y() + std::min(J * span, m_ny * m_cell),
                    m_origin.z() + std::min(K * span, m_nz * m_cell));
    };
    auto empty = [&](int I, int J, int K) {
        if (I < 0 || J < 0 || K < 0 || I >= cx || J >= cy || K >= cz) return true;
        return solid[at(I, J, K)] == 0;
    };
    // One quad per face between a solid cube and air, wound counter-clockwise seen from outside.
    auto face = [&](const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& n) {
        mesh.addQuad(mesh.addVertex(p0, n), mesh.addVertex(p1, n), mesh.addVertex(p2, n),
                     mesh.addVertex(p3, n));
    };
    for (int K = 0; K < cz; ++K) {
        for (int J = 0; J < cy; ++J) {
            for (int I = 0; I < cx; ++I) {
                if (solid[at(I, J, K)] == 0) continue;
                const Vec3 a = corner(I, J, K);
                const Vec3 b = corner(I + 1, J + 1, K + 1);
                const Vec3 p000 = a;
                const Vec3 p100(b.x(), a.y(), a.z());
                const Vec3 p010(a.x(), b.y(), a.z());
                const Vec3 p110(b.x(), b.y(), a.z());
                const Vec3 p001(a.x(), a.y(), b.z());
                const Vec3 p101(b.x(), a.y(), b.z());
                const Vec3 p011(a.x(), b.y(), b.z());
                const Vec3 p111 = b;
                if (empty(I - 1, J, K)) face(p000, p001, p011, p010, -Vec3::UnitX());
                if (empty(I + 1, J, K)) face(p100, p110, p111, p101, Vec3::UnitX());
                if (empty(I, J - 1, K)) face(p000, p100, p101, p001, -Vec3::UnitY());
                if (empty(I, J + 1, K)) face(p010, p011, p111, p110, Vec3::UnitY());
                if (empty(I, J, K - 1)) face(p000, p010, p110, p100, -Vec3::UnitZ());
                if (empty(I, J, K + 1)) face(p001, p101, p111, p011, Vec3::UnitZ());
            }
        }
    }
    return mesh;
}

}  // namespace kerf::graphics
