#include "core/canon/path_statistics.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::canon {

double arcLengthMm(const Pose& start, const ArcMove& arc) {
    PlaneAxes axes = planeAxes(arc.plane);
    Vec2 center(arc.center[axisIndex(axes.first)], arc.center[axisIndex(axes.second)]);
    Vec2 from(start[axes.first], start[axes.second]);
    double planar = (from - center).norm() * std::fabs(arc.sweepRad);
    double axial = arc.target[axes.normal] - start[axes.normal];
    return std::hypot(planar, axial);
}

PathStatistics::PathStatistics(double rapidMmPerS) : m_rapidMmPerS(rapidMmPerS) {
    m_feedBounds.min.fill(0.0);
    m_feedBounds.max.fill(0.0);
}

void PathStatistics::addFeedPoint(const Pose& pose) {
    if (m_feedBounds.empty) {
        m_feedBounds.min = pose.values;
        m_feedBounds.max = pose.values;
        m_feedBounds.empty = false;
        return;
    }
    for (size_t i = 0; i < pose.values.size(); ++i) {
        m_feedBounds.min[i] = std::min(m_feedBounds.min[i], pose.values[i]);
        m_feedBounds.max[i] = std::max(m_feedBounds.max[i], pose.values[i]);
    }
}

void PathStatistics::addFeedTime(double lengthMm, double feed) {
    double mmPerMin = m_feedMode == FeedMode::PerRevolution ? feed * m_spindleRpm : feed;
    if (mmPerMin > 0.0) m_timeS += lengthMm / mmPerMin * 60.0;
}

void PathStatistics::consume(const Command& command) {
    const CommandBody& body = command.body;
    if (const auto* rapid = std::get_if<RapidMove>(&body)) {
        double length = (rapid->target.xyz() - m_position.xyz()).norm();
        ++m_rapidCount;
        m_rapidLength += length;
        if (m_rapidMmPerS > 0.0) m_timeS += length / m_rapidMmPerS;
        m_position = rapid->target;
    } else if (const auto* line = std::get_if<LinearMove>(&body)) {
        double length = (line->target.xyz() - m_position.xyz()).norm();
        ++m_feedCount;
        m_feedLength += length;
        addFeedTime(length, line->feed);
        addFeedPoint(m_position);
        addFeedPoint(line->target);
        m_position = line->target;
    } else if (const auto* arc = std::get_if<ArcMove>(&body)) {
        double length = arcLengthMm(m_position, *arc);
        ++m_feedCount;
        m_feedLength += length;
        addFeedTime(length, arc->feed);
        addFeedPoint(m_position);
        addFeedPoint(arc->target);
        PlaneAxes axes = planeAxes(arc->plane);
        Box2 box;
        Vec2 center(arc->center[axisIndex(axes.first)], arc->center[axisIndex(axes.second)]);
        addArcExtremes(box, center, Vec2(m_position[axes.first], m_position[axes.second]),
                       arc->sweepRad);
        Pose corner = m_position;
        corner[axes.first] = box.min.x();
        corner[axes.second] = box.min.y();
        addFeedPoint(corner);
        corner[axes.first] = box.max.x();
        corner[axes.second] = box.max.y();
        addFeedPoint(corner);
        m_position = arc->target;
    } else if (const auto* synced = std::get_if<SpindleSyncedMove>(&body)) {
        double length = (synced->target.xyz() - m_position.xyz()).norm();
        ++m_feedCount;
        m_feedLength += length;
        if (synced->leadMmPerRev > 0.0 && m_spindleRpm > 0.0) {
            m_timeS += length / (synced->leadMmPerRev * m_spindleRpm) * 60.0;
        }
        addFeedPoint(m_position);
        addFeedPoint(synced->target);
        m_position = synced->target;
    } else if (const auto* probe = std::get_if<ProbeMove>(&body)) {
        double length = (probe->target.xyz() - m_position.xyz()).norm();
        ++m_feedCount;
        m_feedLength += length;
        addFeedTime(length, probe->feed);
        addFeedPoint(m_position);
        addFeedPoint(probe->target);
        m_position = probe->target;
    } else if (const auto* dwell = std::get_if<Dwell>(&body)) {
        m_timeS += std::max(0.0, dwell->seconds);
    } else if (std::holds_alternative<ToolChange>(body)) {
        ++m_toolChanges;
    } else if (const auto* spindle = std::get_if<SpindleControl>(&body)) {
        m_spindleRpm = spindle->direction == SpindleDirection::Stopped ? 0.0 : spindle->speedRpm;
    } else if (const auto* mode = std::get_if<SetFeedMode>(&body)) {
        m_feedMode = mode->mode;
    }
}

}  // namespace kerf::canon
