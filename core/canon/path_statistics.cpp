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

void PathStatistics::addFeedMove(const Pose& target) {
    if (!m_positionCounted) addFeedPoint(m_position);
    addFeedPoint(target);
}

void PathStatistics::consume(const Command& command) {
    const CommandBody& body = command.body;
    if (const auto* rapid = std::get_if<RapidMove>(&body)) {
        double length = (rapid->target.xyz() - m_position.xyz()).norm();
        ++m_rapidCount;
        m_rapidLength += length;
        m_position = rapid->target;
        m_positionCounted = false;
    } else if (const auto* line = std::get_if<LinearMove>(&body)) {
        double length = (line->target.xyz() - m_position.xyz()).norm();
        ++m_feedCount;
        m_feedLength += length;
        addFeedMove(line->target);
        m_position = line->target;
        m_positionCounted = true;
    } else if (const auto* arc = std::get_if<ArcMove>(&body)) {
        double length = arcLengthMm(m_position, *arc);
        ++m_feedCount;
        m_feedLength += length;
        addFeedMove(arc->target);
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
        m_positionCounted = true;
    } else if (const auto* synced = std::get_if<SpindleSyncedMove>(&body)) {
        double length = (synced->target.xyz() - m_position.xyz()).norm();
        ++m_feedCount;
        m_feedLength += length;
        addFeedMove(synced->target);
        m_position = synced->target;
        m_positionCounted = true;
    } else if (const auto* probe = std::get_if<ProbeMove>(&body)) {
        double length = (probe->target.xyz() - m_position.xyz()).norm();
        ++m_feedCount;
        m_feedLength += length;
        addFeedMove(probe->target);
        m_position = probe->target;
        m_positionCounted = true;
    } else if (std::holds_alternative<ToolChange>(body)) {
        ++m_toolChanges;
    }
}

}  // namespace kerf::canon
