#include "core/workpiece/removed_material.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace kerf::workpiece {

namespace {

bool inBox(const Sweep& sweep, const Vec3& p) {
    return (p.array() >= sweep.boxMin.array()).all() && (p.array() <= sweep.boxMax.array()).all();
}

}  // namespace

int64_t RemovedMaterial::cellOf(double coordinate) {
    return static_cast<int64_t>(std::floor(coordinate / kCell));
}

uint64_t RemovedMaterial::key(int64_t ix, int64_t iy) {
    return (static_cast<uint64_t>(ix) << 32) ^ static_cast<uint64_t>(static_cast<uint32_t>(iy));
}

void RemovedMaterial::add(const Sweep& sweep) {
    if (m_sweeps.size() >= kMaxSweeps) {
        m_overflowed = true;
        return;
    }
    const auto index = static_cast<uint32_t>(m_sweeps.size());
    m_sweeps.push_back(sweep);
    const int64_t x0 = cellOf(sweep.boxMin.x());
    const int64_t x1 = cellOf(sweep.boxMax.x());
    const int64_t y0 = cellOf(sweep.boxMin.y());
    const int64_t y1 = cellOf(sweep.boxMax.y());
    const auto cells = static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1);
    if (cells > static_cast<double>(kMaxCellsPerSweep)) {
        m_large.push_back(index);
        return;
    }
    for (int64_t ix = x0; ix <= x1; ++ix) {
        for (int64_t iy = y0; iy <= y1; ++iy)
            m_cells[key(ix, iy)].push_back(index);
    }
}

void RemovedMaterial::addLine(const Cutter& cutter, const Vec3& from, const Vec3& to) {
    if (cutter.radius <= 0.0) return;
    add(sweepAlongLine(cutter, from, to));
}

void RemovedMaterial::addArc(const Cutter& cutter, const Vec3& from, const Vec3& to,
                             const Vec3& centre, Plane plane, double sweepRad) {
    if (cutter.radius <= 0.0) return;
    // In the plane's frame (first, second, normal): the arc about the centre, the normal
    // coordinate moving linearly from the start to the target.
    const Vec3 a = toPlaneFrame(plane, from);
    const Vec3 b = toPlaneFrame(plane, to);
    const Vec3 c = toPlaneFrame(plane, centre);
    const double radius = Vec2(a.x() - c.x(), a.y() - c.y()).norm();
    const double start = std::atan2(a.y() - c.y(), a.x() - c.x());
    if (plane == Plane::XY && a.z() == b.z()) {
        add(sweepAlongArc(cutter, ArcSweep{Vec2(c.x(), c.y()), a.z(), radius, start, sweepRad}));
        return;
    }
    // Chords: the sagitta radius (1 - cos(step / 2)) stays within the tolerance.
    int chords = 1;
    if (radius > kChordTolerance) {
        const double step = 2.0 * std::acos(1.0 - kChordTolerance / radius);
        chords = std::clamp(static_cast<int>(std::ceil(std::abs(sweepRad) / step)), 1, 100000);
    }
    Vec3 previous = from;
    for (int i = 1; i <= chords; ++i) {
        const double t = static_cast<double>(i) / chords;
        const double angle = start + t * sweepRad;
        const Vec3 local(c.x() + radius * std::cos(angle), c.y() + radius * std::sin(angle),
                         a.z() + t * (b.z() - a.z()));
        const Vec3 next = i == chords ? to : fromPlaneFrame(plane, local);
        add(sweepAlongLine(cutter, previous, next));
        previous = next;
    }
}

bool RemovedMaterial::containsMovingDisc(const Vec3& a, const Vec3& b, double radius) const {
    auto holds = [&](uint32_t index) {
        const Sweep& sweep = m_sweeps[index];
        if (!std::holds_alternative<LineSweep>(sweep.path) || !inBox(sweep, a) || !inBox(sweep, b))
            return false;
        // The thinner cutter dilated by the disc is the real one while its corner keeps its
        // radius; its box lies within the real one's.
        Sweep thinner = sweep;
        thinner.cutter.radius -= radius;
        if (thinner.cutter.radius < thinner.cutter.cornerRadius) return false;
        return sweepDistance(thinner, a) <= 0.0 && sweepDistance(thinner, b) <= 0.0;
    };
    if (auto cell = m_cells.find(key(cellOf(a.x()), cellOf(a.y()))); cell != m_cells.end()) {
        for (uint32_t index : cell->second)
            if (holds(index)) return true;
    }
    for (uint32_t index : m_large)
        if (holds(index)) return true;
    return false;
}

double RemovedMaterial::depth(const Vec3& p) const {
    double least = std::numeric_limits<double>::infinity();
    auto look = [&](uint32_t index) {
        const Sweep& sweep = m_sweeps[index];
        if (inBox(sweep, p)) least = std::min(least, sweepDistance(sweep, p));
    };
    if (auto cell = m_cells.find(key(cellOf(p.x()), cellOf(p.y()))); cell != m_cells.end()) {
        for (uint32_t index : cell->second)
            look(index);
    }
    for (uint32_t index : m_large)
        look(index);
    return -least;
}

}  // namespace kerf::workpiece
