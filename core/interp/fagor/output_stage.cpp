#include "core/interp/fagor/output_stage.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

Pose plus(Pose p, const Pose& offset) {
    for (size_t i = 0; i < p.values.size(); ++i)
        p.values[i] += offset.values[i];
    return p;
}

double planarLength(const ContourElement& e) {
    double axial = 0.0;
    const PlaneAxes axes = planeAxes(e.plane);
    for (int i = 0; i < kAxisCount; ++i) {
        const auto a = static_cast<Axis>(i);
        if (a == axes.first || a == axes.second) continue;
        const double d = e.end[a] - e.start[a];
        axial += d * d;
    }
    return std::sqrt(e.planarLength() * e.planarLength() + axial);
}

}  // namespace

void OutputStage::reset(const Pose& position) {
    m_position = position;
    m_unscaled = position;
    m_failed = false;
    m_error.reset();
}

void OutputStage::setAxisScale(Axis axis, double factor) {
    const auto i = static_cast<size_t>(axisIndex(axis));
    m_scale[i] = factor;
    if (factor == 1.0) {
        // From here on the axis follows the program again.
        m_scaledAxes = static_cast<AxisMask>(m_scaledAxes & ~axisBit(axis));
        return;
    }
    // Displacements from here on are scaled: the output continues from where the axis is.
    m_scaledAxes = static_cast<AxisMask>(m_scaledAxes | axisBit(axis));
    m_anchorOut[i] = m_position.values[i];
    m_anchorProgrammed[i] = m_unscaled.values[i];
}

Pose OutputStage::scaled(const Pose& p) const {
    Pose out = p;
    for (size_t i = 0; i < out.values.size(); ++i) {
        if ((m_scaledAxes & (1u << i)) == 0) continue;
        out.values[i] = m_anchorOut[i] + m_scale[i] * (p.values[i] - m_anchorProgrammed[i]);
    }
    return out;
}

std::optional<interp::PathError> OutputStage::takeError() {
    auto e = m_error;
    m_error.reset();
    return e;
}

bool OutputStage::check(const ContourElement& path, const SourceLocation& at) {
    if (m_zones == nullptr || !m_zones->anyEnabled()) return true;
    ContourElement machine = path;
    machine.start = plus(path.start, m_machineOffset);
    machine.end = plus(path.end, m_machineOffset);
    if (path.kind == ContourElement::Kind::Arc) {
        machine.center = path.center + path.inPlane(m_machineOffset);
    }
    if (auto zone = m_zones->violation(machine)) {
        m_error = interp::PathError{at,
                                    "work-zone",
                                    *zone == 1   ? KERF_TR_NOOP("the move violates work zone 1")
                                    : *zone == 2 ? KERF_TR_NOOP("the move violates work zone 2")
                                    : *zone == 3 ? KERF_TR_NOOP("the move violates work zone 3")
                                    : *zone == 4 ? KERF_TR_NOOP("the move violates work zone 4")
                                                 : KERF_TR_NOOP("the move violates work zone 5"),
                                    {}};
        m_failed = true;
        return false;
    }
    return true;
}

void OutputStage::addDistance(const ContourElement& path) {
    for (size_t i = 0; i < m_distance.size(); ++i) {
        m_distance[i] += std::fabs(path.end.values[i] - path.start.values[i]);
    }
    if (path.kind != ContourElement::Kind::Arc) return;
    // In the plane an arc travels more than its chord: the variation of each coordinate between
    // the quadrant points it passes.
    const PlaneAxes axes = planeAxes(path.plane);
    const Vec2 r = path.start2() - path.center;
    const double radius = r.norm();
    const double a0 = std::atan2(r.y(), r.x());
    std::vector<double> angles{a0};
    const double quarter = kPi / 2.0;
    const double lo = std::min(a0, a0 + path.sweep);
    const double hi = std::max(a0, a0 + path.sweep);
    for (double k = std::ceil(lo / quarter); k * quarter < hi; k += 1.0)
        angles.push_back(k * quarter);
    angles.push_back(a0 + path.sweep);
    std::sort(angles.begin(), angles.end());
    double dx = 0.0, dy = 0.0;
    for (size_t i = 1; i < angles.size(); ++i) {
        dx += radius * std::fabs(std::cos(angles[i]) - std::cos(angles[i - 1]));
        dy += radius * std::fabs(std::sin(angles[i]) - std::sin(angles[i - 1]));
    }
    const auto first = static_cast<size_t>(axisIndex(axes.first));
    const auto second = static_cast<size_t>(axisIndex(axes.second));
    m_distance[first] += dx - std::fabs(path.end.values[first] - path.start.values[first]);
    m_distance[second] += dy - std::fabs(path.end.values[second] - path.start.values[second]);
}

bool OutputStage::refuseUnsafe(const canon::Command& command) {
    m_error = interp::unsafeValueError(command);
    m_failed = m_error.has_value();
    return m_failed;
}

void OutputStage::consume(const canon::Command& command) {
    if (m_failed || m_target == nullptr) return;
    // Zone checks and scaling compare and scale: they need finite numbers.
    if (refuseUnsafe(command)) return;
    const canon::CommandBody& body = command.body;
    canon::Command out = command;
    ContourElement path;
    Pose target;
    if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) {
        target = rapid->target;
    } else if (const auto* line = std::get_if<canon::LinearMove>(&body)) {
        target = line->target;
    } else if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body)) {
        target = synced->target;
    } else if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) {
        target = probe->target;
    } else if (const auto* arc = std::get_if<canon::ArcMove>(&body)) {
        target = arc->target;
    } else {
        m_target->consume(command);
        return;
    }
    const Pose to = scaling() ? scaled(target) : target;
    if (const auto* arc = std::get_if<canon::ArcMove>(&body)) {
        const PlaneAxes axes = planeAxes(arc->plane);
        const double k1 = m_scale[static_cast<size_t>(axisIndex(axes.first))];
        const double k2 = m_scale[static_cast<size_t>(axisIndex(axes.second))];
        const bool scaledPlane = (m_scaledAxes & (axisBit(axes.first) | axisBit(axes.second))) != 0;
        if (scaledPlane && k1 != k2) {
            m_error = interp::PathError{command.location,
                                        "scaling",
                                        KERF_TR_NOOP("an arc cannot be scaled differently along "
                                                     "the two axes of its plane (G72)"),
                                        {}};
            m_failed = true;
            return;
        }
        Pose centre = m_unscaled;
        centre.setXyz(arc->center);
        const Pose c = scaling() ? scaled(centre) : centre;
        const Vec2 center(c[axes.first], c[axes.second]);
        path = ContourElement::arc(arc->plane, m_position, to, center, arc->sweepRad);
        canon::ArcMove moved = *arc;
        moved.target = to;
        moved.center = c.xyz();
        if (scaling()) {
            const ContourElement before = ContourElement::arc(
                arc->plane, m_unscaled, target,
                Vec2(arc->center[axisIndex(axes.first)], arc->center[axisIndex(axes.second)]),
                arc->sweepRad);
            const double l0 = planarLength(before);
            if (l0 > 0.0) moved.feed *= planarLength(path) / l0;
        }
        out.body = moved;
    } else {
        path = ContourElement::line(Plane::ZX, m_position, to);
        if (scaling()) {
            const double l0 = (target.xyz() - m_unscaled.xyz()).norm();
            const double l1 = (to.xyz() - m_position.xyz()).norm();
            if (auto* line = std::get_if<canon::LinearMove>(&out.body)) {
                line->target = to;
                if (l0 > 0.0) line->feed *= l1 / l0;
            } else if (auto* rapid = std::get_if<canon::RapidMove>(&out.body)) {
                rapid->target = to;
            } else if (auto* synced = std::get_if<canon::SpindleSyncedMove>(&out.body)) {
                synced->target = to;
            } else if (auto* probe = std::get_if<canon::ProbeMove>(&out.body)) {
                probe->target = to;
            }
        }
    }
    if (refuseUnsafe(out) || !check(path, command.location)) return;
    addDistance(path);
    m_position = to;
    m_unscaled = target;
    m_target->consume(out);
}

}  // namespace kerf::fagor
