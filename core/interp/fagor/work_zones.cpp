#include "core/interp/fagor/work_zones.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kerf::fagor {

namespace {

constexpr double kEps = 1e-9;

bool validZone(int zone) {
    return zone >= 1 && zone <= WorkZones::kCount;
}

}  // namespace

void WorkZones::setLower(int zone, Axis axis, double value) {
    if (validZone(zone))
        m_zones[static_cast<size_t>(zone - 1)].lower[static_cast<size_t>(axisIndex(axis))] = value;
}

void WorkZones::setUpper(int zone, Axis axis, double value) {
    if (validZone(zone))
        m_zones[static_cast<size_t>(zone - 1)].upper[static_cast<size_t>(axisIndex(axis))] = value;
}

void WorkZones::setMode(int zone, Mode mode) {
    if (validZone(zone)) m_zones[static_cast<size_t>(zone - 1)].mode = mode;
}

WorkZones::Mode WorkZones::mode(int zone) const {
    return validZone(zone) ? m_zones[static_cast<size_t>(zone - 1)].mode : Mode::Disabled;
}

std::optional<double> WorkZones::lower(int zone, Axis axis) const {
    if (!validZone(zone)) return std::nullopt;
    return m_zones[static_cast<size_t>(zone - 1)].lower[static_cast<size_t>(axisIndex(axis))];
}

std::optional<double> WorkZones::upper(int zone, Axis axis) const {
    if (!validZone(zone)) return std::nullopt;
    return m_zones[static_cast<size_t>(zone - 1)].upper[static_cast<size_t>(axisIndex(axis))];
}

bool WorkZones::anyEnabled() const {
    return std::any_of(m_zones.begin(), m_zones.end(),
                       [](const Zone& z) { return z.mode != Mode::Disabled; });
}

// Strictly inside the limits (a no-entry zone may be touched, a no-exit zone may be reached).
bool WorkZones::inside(const Zone& zone, const Pose& p) const {
    for (size_t i = 0; i < static_cast<size_t>(kAxisCount); ++i) {
        if (zone.lower[i] && !(p.values[i] > *zone.lower[i] + kEps)) return false;
        if (zone.upper[i] && !(p.values[i] < *zone.upper[i] - kEps)) return false;
    }
    return true;
}

namespace {

bool outsideClosed(const std::array<std::optional<double>, kAxisCount>& lower,
                   const std::array<std::optional<double>, kAxisCount>& upper, const Pose& p) {
    for (size_t i = 0; i < static_cast<size_t>(kAxisCount); ++i) {
        if (lower[i] && p.values[i] < *lower[i] - 1e-9) return true;
        if (upper[i] && p.values[i] > *upper[i] + 1e-9) return true;
    }
    return false;
}

// Parameters along the path where it crosses a limit, with 0 and 1, sorted: between two of them
// the path is either inside or outside the zone.
std::vector<double> crossings(const std::array<std::optional<double>, kAxisCount>& lower,
                              const std::array<std::optional<double>, kAxisCount>& upper,
                              const ContourElement& path) {
    std::vector<double> ts{0.0, 1.0};
    const PlaneAxes axes = planeAxes(path.plane);
    const bool arc = path.kind == ContourElement::Kind::Arc;
    for (size_t i = 0; i < static_cast<size_t>(kAxisCount); ++i) {
        const auto axis = static_cast<Axis>(i);
        for (const auto& limit : {lower[i], upper[i]}) {
            if (!limit) continue;
            const double v = *limit;
            if (arc && (axis == axes.first || axis == axes.second)) {
                const bool first = axis == axes.first;
                const double r = path.radius();
                const double c = first ? path.center.x() : path.center.y();
                const double other = first ? path.center.y() : path.center.x();
                const double d = v - c;
                if (std::fabs(d) > r) continue;
                const double h = std::sqrt(std::max(0.0, r * r - d * d));
                for (double s : {h, -h}) {
                    const Vec2 p = first ? Vec2(v, other + s) : Vec2(other + s, v);
                    const double t = path.paramOf(p);
                    if (t > 0.0 && t < 1.0) ts.push_back(t);
                }
            } else {
                const double a = path.start.values[i];
                const double b = path.end.values[i];
                if (std::fabs(b - a) < 1e-15) continue;
                const double t = (v - a) / (b - a);
                if (t > 0.0 && t < 1.0) ts.push_back(t);
            }
        }
    }
    std::sort(ts.begin(), ts.end());
    return ts;
}

}  // namespace

bool WorkZones::enters(const Zone& zone, const ContourElement& path) const {
    if (inside(zone, path.start) || inside(zone, path.end)) return true;
    const std::vector<double> ts = crossings(zone.lower, zone.upper, path);
    for (size_t i = 0; i + 1 < ts.size(); ++i) {
        if (ts[i + 1] - ts[i] < 1e-12) continue;
        if (inside(zone, path.poseAt((ts[i] + ts[i + 1]) / 2.0))) return true;
    }
    return false;
}

bool WorkZones::leaves(const Zone& zone, const ContourElement& path) const {
    if (outsideClosed(zone.lower, zone.upper, path.end)) return true;
    const std::vector<double> ts = crossings(zone.lower, zone.upper, path);
    for (size_t i = 0; i + 1 < ts.size(); ++i) {
        if (outsideClosed(zone.lower, zone.upper, path.poseAt((ts[i] + ts[i + 1]) / 2.0))) {
            return true;
        }
    }
    return false;
}

std::optional<int> WorkZones::violation(const ContourElement& path) const {
    for (size_t i = 0; i < m_zones.size(); ++i) {
        const Zone& zone = m_zones[i];
        if (zone.mode == Mode::NoEntry && enters(zone, path)) return static_cast<int>(i) + 1;
        if (zone.mode == Mode::NoExit && leaves(zone, path)) return static_cast<int>(i) + 1;
    }
    return std::nullopt;
}

}  // namespace kerf::fagor
