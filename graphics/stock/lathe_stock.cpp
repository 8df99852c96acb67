#include "graphics/stock/lathe_stock.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::graphics {

namespace {

double distanceToSegment(double px, double pz, double ax, double az, double bx, double bz) {
    const double dx = bx - ax;
    const double dz = bz - az;
    const double len2 = dx * dx + dz * dz;
    double t = len2 > 0.0 ? ((px - ax) * dx + (pz - az) * dz) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - ax - t * dx, pz - az - t * dz);
}

// True when the segment p0-p1 meets the convex polygon (Cyrus-Beck clipping).
bool segmentMeetsConvex(double p0x, double p0z, double p1x, double p1z,
                        const std::vector<std::pair<double, double>>& poly, double orientation) {
    double t0 = 0.0;
    double t1 = 1.0;
    const double dx = p1x - p0x;
    const double dz = p1z - p0z;
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const auto [ax, az] = poly[i];
        const auto [bx, bz] = poly[(i + 1) % n];
        // Inside: orientation * cross(b - a, p - a) >= 0.
        const double ex = bx - ax;
        const double ez = bz - az;
        const double c0 = orientation * (ex * (p0z - az) - ez * (p0x - ax));
        const double dc = orientation * (ex * dz - ez * dx);
        if (std::fabs(dc) < 1e-15) {
            if (c0 < 0.0) return false;
            continue;
        }
        const double t = -c0 / dc;
        if (dc > 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

LatheStock::LatheStock(const LatheBar& bar, double cellMm, size_t maxCells) : m_bar(bar) {
    auto finiteOr = [](double v, double fallback) { return std::isfinite(v) ? v : fallback; };
    m_bar.radiusMm = std::fabs(finiteOr(bar.radiusMm, 0.0));
    m_bar.innerRadiusMm =
        std::clamp(std::fabs(finiteOr(bar.innerRadiusMm, 0.0)), 0.0, m_bar.radiusMm);
    m_bar.zMin = std::min(finiteOr(bar.zMin, 0.0), finiteOr(bar.zMax, 0.0));
    m_bar.zMax = std::max(finiteOr(bar.zMin, 0.0), finiteOr(bar.zMax, 0.0));
    double cell = std::isfinite(cellMm) && cellMm > 0.0 ? cellMm : 0.1;
    const double length = m_bar.zMax - m_bar.zMin;
    maxCells = std::max<size_t>(maxCells, 1);
    while ((std::ceil(m_bar.radiusMm / cell) + 1.0) * (std::ceil(length / cell) + 1.0) >
           static_cast<double>(maxCells)) {
        cell *= 1.25;
    }
    m_cell = cell;
    m_nr = std::max(1, static_cast<int>(std::ceil(m_bar.radiusMm / cell - 1e-9)));
    m_nz = std::max(1, static_cast<int>(std::ceil(length / cell - 1e-9)));
    m_z0 = m_bar.zMin;
    m_cells.assign(static_cast<size_t>(m_nr) * static_cast<size_t>(m_nz), 0);
    for (int iz = 0; iz < m_nz; ++iz) {
        for (int ir = 0; ir < m_nr; ++ir) {
            const double r = (ir + 0.5) * m_cell;
            const double z = m_z0 + (iz + 0.5) * m_cell;
            const bool inside = r <= m_bar.radiusMm && r >= m_bar.innerRadiusMm && z <= m_bar.zMax;
            m_cells[index(ir, iz)] = inside ? 1 : 0;
        }
    }
    m_initialVolume = volumeMm3();
}

LatheStock LatheStock::revolved(const std::vector<std::pair<double, double>>& outline,
                                std::pair<double, double> side, const LatheBar* bar, double cellMm,
                                size_t maxCells) {
    std::vector<std::pair<double, double>> polygon;
    for (const auto& [r, z] : outline) {
        if (std::isfinite(r) && std::isfinite(z)) polygon.emplace_back(std::fabs(r), z);
    }
    if (polygon.empty()) return LatheStock(LatheBar{0.0, 0.0, 0.0, 0.0}, cellMm, maxCells);
    double rMax = bar != nullptr ? bar->radiusMm : 0.0;
    double zMin = bar != nullptr ? bar->zMin : HUGE_VAL;
    double zMax = bar != nullptr ? bar->zMax : -HUGE_VAL;
    for (const auto& [r, z] : polygon) {
        rMax = std::max(rMax, r);
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
    }
    // Close the outline from its last point back to its first along the material side.
    const auto first = polygon.front();
    const auto last = polygon.back();
    const auto [sr, sz] = side;
    if (std::fabs(sr) >= std::fabs(sz)) {
        const double r = sr < 0.0 ? (bar != nullptr ? bar->innerRadiusMm : 0.0) : rMax;
        polygon.emplace_back(r, last.second);
        polygon.emplace_back(r, first.second);
    } else {
        const double z = sz < 0.0 ? zMin : zMax;
        polygon.emplace_back(last.first, z);
        polygon.emplace_back(first.first, z);
    }
    double rLow = HUGE_VAL;
    for (const auto& [r, z] : polygon)
        rLow = std::min(rLow, r);
    LatheStock stock(LatheBar{rMax, rLow, zMin, zMax}, cellMm, maxCells);
    stock.keepInside(polygon);
    return stock;
}

void LatheStock::keepInside(const std::vector<std::pair<double, double>>& polygon) {
    const size_t n = polygon.size();
    std::vector<double> crossings;
    for (int iz = 0; iz < m_nz; ++iz) {
        // The polygon's crossings of this row (even-odd rule), then the cells between pairs.
        const double z = m_z0 + (iz + 0.5) * m_cell;
        crossings.clear();
        for (size_t i = 0; i < n; ++i) {
            const auto [r0, z0] = polygon[i];
            const auto [r1, z1] = polygon[(i + 1) % n];
            if ((z0 <= z) == (z1 <= z)) continue;
            crossings.push_back(r0 + (z - z0) * (r1 - r0) / (z1 - z0));
        }
        std::sort(crossings.begin(), crossings.end());
        for (int ir = 0; ir < m_nr; ++ir) {
            const double r = (ir + 0.5) * m_cell;
            const auto passed = std::upper_bound(crossings.begin(), crossings.end(), r);
            const bool inside = (passed - crossings.begin()) % 2 == 1;
            if (!inside) m_cells[index(ir, iz)] = 0;
        }
    }
    m_initialVolume = volumeMm3();
}

double LatheStock::volumeMm3() const {
    double sum = 0.0;
    for (int iz = 0; iz < m_nz; ++iz) {
        for (int ir = 0; ir < m_nr; ++ir) {
            if (m_cells[index(ir, iz)] != 0) sum += (ir + 0.5);
        }
    }
    return 2.0 * kPi * sum * m_cell * m_cell * m_cell;
}

bool LatheStock::cut(double ax, double az, double bx, double bz, const LatheInsert& insert) {
    if (!std::isfinite(ax) || !std::isfinite(az) || !std::isfinite(bx) || !std::isfinite(bz)) {
        return false;
    }
    // A sharp insert (R 0) gets a nose of just over half a cell: its degenerate outline would miss
    // every cell centre when the path runs along cell borders. The cut may then reach one cell
    // (the resolution) beyond the path. A blade or drill narrower than a cell gets a cell's width
    // for the same reason.
    LatheInsert shape = insert;
    const bool turning = insert.kind == LatheToolKind::Turning;
    const double given =
        std::isfinite(insert.noseRadiusMm) ? std::max(0.0, insert.noseRadiusMm) : 0.0;
    shape.noseRadiusMm = turning ? std::max(given, 0.5 * m_cell * 1.0001) : 0.0;
    const double width = std::isfinite(insert.widthMm) ? std::max(0.0, insert.widthMm) : 0.0;
    shape.widthMm = std::max(width, m_cell * 1.0001);
    const double nose = shape.noseRadiusMm;
    const auto [ox, oz] = shape.noseCentreOffset();
    // The body of a drill or face-grooving blade runs past the bar's far end: its sides are what
    // cut. A blade plunging along X needs no body: the holder rule below clears behind it.
    const bool radialBlade =
        !turning && !shape.groovesAlongZ() && insert.kind == LatheToolKind::Grooving;
    const double gridLength = (m_nz + m_nr) * m_cell;
    const double bodyMm =
        radialBlade ? m_cell : gridLength + std::max(std::fabs(az - m_z0), std::fabs(bz - m_z0));
    const auto outline = shape.outline(24, bodyMm);
    const bool body = !turning || (shape.includedAngleDeg > 0.0 && shape.edgeLengthMm > 0.0);
    // Reach of the shape around the programmed point.
    double reach = nose + std::hypot(ox, oz);
    double orientation = 1.0;
    if (body) {
        double area = 0.0;
        for (size_t i = 0; i < outline.size(); ++i) {
            const auto [x0, z0] = outline[i];
            const auto [x1, z1] = outline[(i + 1) % outline.size()];
            area += x0 * z1 - x1 * z0;
            reach = std::max(reach, std::hypot(x0, z0));
        }
        orientation = area >= 0.0 ? 1.0 : -1.0;
    }
    // A tiny nose still cuts a line one cell wide.
    const double radius = std::max(nose, 0.5 * m_cell * 0.999);
    const double rmax = std::max(std::fabs(ax), std::fabs(bx)) + reach;
    const double rmin = std::max(0.0, std::min(std::fabs(ax), std::fabs(bx)) - reach);
    const double zmin = std::min(az, bz) - reach;
    const double zmax = std::max(az, bz) + reach;
    if (zmax < m_z0 || zmin > m_z0 + m_nz * m_cell || rmin > m_nr * m_cell) return false;
    const bool crossesAxis = std::min(ax, bx) - reach < 0.0;
    const int ir0 =
        std::max(0, static_cast<int>(std::floor(rmin / m_cell)) - (crossesAxis ? m_nr : 0));
    const int ir1 = std::min(m_nr - 1, static_cast<int>(std::ceil(rmax / m_cell)));
    const int iz0 = std::max(0, static_cast<int>(std::floor((zmin - m_z0) / m_cell)));
    const int iz1 = std::min(m_nz - 1, static_cast<int>(std::ceil((zmax - m_z0) / m_cell)));
    bool removed = false;
    auto inside = [&](double px, double pz) {
        if (!body) {
            return distanceToSegment(px, pz, ax + ox, az + oz, bx + ox, bz + oz) <= radius;
        }
        // p in shape + segment  <=>  segment (p - a) .. (p - b) meets the shape.
        return segmentMeetsConvex(px - ax, pz - az, px - bx, pz - bz, outline, orientation);
    };
    // The holder behind the insert is solid: an external tool (tip towards the axis or along Z)
    // clears everything radially outside the swept insert, a boring tool (tip away from the
    // axis) everything inside it. Each ring of cells is cleared from the first one the insert
    // sweeps, outwards or inwards.
    // A drill and a face-grooving blade carry their body in their outline: no holder rule.
    const bool holder = turning || radialBlade;
    const bool boring = LatheInsert::tipDirection(insert.locationCode).first > 0.0;
    auto sweeps = [&](int ir, double z) {
        const double r = (ir + 0.5) * m_cell;
        return inside(r, z) || (crossesAxis && inside(-r, z));
    };
    for (int iz = iz0; iz <= iz1; ++iz) {
        const double z = m_z0 + (iz + 0.5) * m_cell;
        int first = -1;
        if (boring) {
            for (int ir = ir1; ir >= std::max(0, ir0) && first < 0; --ir) {
                if (sweeps(ir, z)) first = ir;
            }
        } else {
            for (int ir = std::max(0, ir0); ir <= ir1 && first < 0; ++ir) {
                if (sweeps(ir, z)) first = ir;
            }
        }
        if (first < 0) continue;
        if (!holder) {
            for (int ir = first; ir <= ir1; ++ir) {
                if (!sweeps(ir, z)) continue;
                uint8_t& cell = m_cells[index(ir, iz)];
                removed = removed || cell != 0;
                cell = 0;
            }
            continue;
        }
        const int from = boring ? 0 : first;
        const int to = boring ? first : m_nr - 1;
        for (int ir = from; ir <= to; ++ir) {
            uint8_t& cell = m_cells[index(ir, iz)];
            removed = removed || cell != 0;
            cell = 0;
        }
    }
    return removed;
}

Mesh LatheStock::mesh(double sweepDeg, int angularSteps, int maxSide) const {
    Mesh mesh;
    if (m_cells.empty()) return mesh;
    const int side = std::max(2, maxSide);
    const int step = std::max(1, (std::max(m_nr, m_nz) + side - 1) / side);
    const int nr = (m_nr + step - 1) / step;
    const int nz = (m_nz + step - 1) / step;
    const double span = m_cell * step;
    // A coarse cell holds material when most of its fine cells do.
    std::vector<uint8_t> grid(static_cast<size_t>(nr) * static_cast<size_t>(nz), 0);
    for (int z = 0; z < nz; ++z) {
        for (int r = 0; r < nr; ++r) {
            int full = 0;
            int total = 0;
            for (int iz = z * step; iz < std::min(m_nz, (z + 1) * step); ++iz) {
                for (int ir = r * step; ir < std::min(m_nr, (r + 1) * step); ++ir) {
                    full += m_cells[index(ir, iz)];
                    ++total;
                }
            }
            grid[static_cast<size_t>(z) * static_cast<size_t>(nr) + static_cast<size_t>(r)] =
                2 * full >= total && full > 0 ? 1 : 0;
        }
    }
    auto at = [&](int r, int z) {
        if (r < 0 || z < 0 || r >= nr || z >= nz) return false;
        return grid[static_cast<size_t>(z) * static_cast<size_t>(nr) + static_cast<size_t>(r)] != 0;
    };
    const double sweep = degToRad(std::clamp(sweepDeg, 1.0, 360.0));
    const bool full = sweepDeg >= 359.999;
    const int steps = std::max(3, angularSteps);
    // Angles from pi to pi + sweep: the half section keeps Y <= 0, cut faces in Y = 0.
    auto ring = [&](double r, double z, int k) {
        const double a = kPi + sweep * k / steps;
        return Vec3(r * std::cos(a), r * std::sin(a), z);
    };
    auto radialNormal = [&](int k, double sign) {
        const double a = kPi + sweep * k / steps;
        return Vec3(sign * std::cos(a), sign * std::sin(a), 0.0);
    };
    // Boundary edges of the profile, revolved: cylindrical faces (between r and r + 1) and
    // annular faces (between z and z + 1).
    for (int z = 0; z < nz; ++z) {
        for (int r = 0; r < nr; ++r) {
            if (!at(r, z)) continue;
            const double r0 = r * span;
            const double r1 = std::min((r + 1) * span, m_nr * m_cell);
            const double z0 = m_z0 + z * span;
            const double z1 = m_z0 + std::min((z + 1) * span, m_nz * m_cell);
            if (!at(r + 1, z)) {  // outer cylinder at r1
                for (int k = 0; k < steps; ++k) {
                    const uint32_t a = mesh.addVertex(ring(r1, z0, k), radialNormal(k, 1.0));
                    const uint32_t b =
                        mesh.addVertex(ring(r1, z0, k + 1), radialNormal(k + 1, 1.0));
                    const uint32_t c =
                        mesh.addVertex(ring(r1, z1, k + 1), radialNormal(k + 1, 1.0));
                    const uint32_t d = mesh.addVertex(ring(r1, z1, k), radialNormal(k, 1.0));
                    mesh.addQuad(a, b, c, d);
                }
            }
            if (r > 0 && !at(r - 1, z)) {  // inner cylinder at r0 (bore)
                for (int k = 0; k < steps; ++k) {
                    const uint32_t a = mesh.addVertex(ring(r0, z0, k), radialNormal(k, -1.0));
                    const uint32_t b = mesh.addVertex(ring(r0, z1, k), radialNormal(k, -1.0));
                    const uint32_t c =
                        mesh.addVertex(ring(r0, z1, k + 1), radialNormal(k + 1, -1.0));
                    const uint32_t d =
                        mesh.addVertex(ring(r0, z0, k + 1), radialNormal(k + 1, -1.0));
                    mesh.addQuad(a, b, c, d);
                }
            }
            for (int side2 = 0; side2 < 2; ++side2) {
                const int nzNext = side2 == 0 ? z + 1 : z - 1;
                if (at(r, nzNext)) continue;
                const double zf = side2 == 0 ? z1 : z0;
                const Vec3 normal(0, 0, side2 == 0 ? 1.0 : -1.0);
                for (int k = 0; k < steps; ++k) {
                    const uint32_t a = mesh.addVertex(ring(r0, zf, k), normal);
                    const uint32_t b = mesh.addVertex(ring(r1, zf, k), normal);
                    const uint32_t c = mesh.addVertex(ring(r1, zf, k + 1), normal);
                    const uint32_t d = mesh.addVertex(ring(r0, zf, k + 1), normal);
                    if (side2 == 0) {
                        mesh.addQuad(a, b, c, d);
                    } else {
                        mesh.addQuad(a, d, c, b);
                    }
                }
            }
        }
    }
    if (!full) {
        // Section faces in the plane Y = 0 at X = -r (angle pi) and X = +r (angle pi + sweep),
        // one quad per run of material cells along Z in each ring of cells.
        for (int face = 0; face < 2; ++face) {
            const int k = face == 0 ? 0 : steps;
            const double a = kPi + sweep * k / steps;
            // Outward normal of the face: towards the removed half.
            const Vec3 normal = face == 0 ? Vec3(-std::sin(a), std::cos(a), 0.0) * -1.0
                                          : Vec3(-std::sin(a), std::cos(a), 0.0);
            for (int r = 0; r < nr; ++r) {
                const double r0 = r * span;
                const double r1 = std::min((r + 1) * span, m_nr * m_cell);
                int z = 0;
                while (z < nz) {
                    if (!at(r, z)) {
                        ++z;
                        continue;
                    }
                    const int begin = z;
                    while (z < nz && at(r, z))
                        ++z;
                    const double z0 = m_z0 + begin * span;
                    const double z1 = m_z0 + std::min(z * span, m_nz * m_cell);
                    const uint32_t p0 = mesh.addVertex(ring(r0, z0, k), normal);
                    const uint32_t p1 = mesh.addVertex(ring(r1, z0, k), normal);
                    const uint32_t p2 = mesh.addVertex(ring(r1, z1, k), normal);
                    const uint32_t p3 = mesh.addVertex(ring(r0, z1, k), normal);
                    if (face == 0) {
                        mesh.addQuad(p0, p1, p2, p3);
                    } else {
                        mesh.addQuad(p0, p3, p2, p1);
                    }
                }
            }
        }
    }
    return mesh;
}

}  // namespace kerf::graphics
