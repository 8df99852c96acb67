#include "graphics/toolpath/toolpath_data.h"

#include <algorithm>
#include <utility>

#include "graphics/toolpath/arc_tessellation.h"

namespace kerf::graphics {

const char* moveKindName(MoveKind kind) {
    switch (kind) {
        case MoveKind::Rapid:
            return "rapid";
        case MoveKind::Feed:
            return "feed";
        case MoveKind::Arc:
            return "arc";
        case MoveKind::Synced:
            return "synced";
        case MoveKind::Probe:
            return "probe";
    }
    return "?";
}

void Bounds3::add(const Vec3& p) {
    if (empty) {
        min = p;
        max = p;
        empty = false;
        return;
    }
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
}

void Bounds3::add(const Bounds3& other) {
    if (other.empty) return;
    add(other.min);
    add(other.max);
}

std::optional<uint32_t> ToolpathData::moveOfSegment(size_t segment) const {
    if (segment == 0 || segment >= pointCount()) return std::nullopt;
    auto it =
        std::upper_bound(firstPoint.begin(), firstPoint.end(), static_cast<uint32_t>(segment));
    if (it == firstPoint.begin()) return std::nullopt;
    return static_cast<uint32_t>(std::distance(firstPoint.begin(), it) - 1);
}

std::pair<size_t, size_t> ToolpathData::pointsOfMove(size_t move) const {
    if (move >= firstPoint.size()) return {0, 0};
    const size_t begin = firstPoint[move];
    const size_t end = move + 1 < firstPoint.size() ? firstPoint[move + 1] : pointCount();
    return {begin, end};
}

size_t ToolpathData::memoryBytes() const {
    return xyz.capacity() * sizeof(float) + firstPoint.capacity() * sizeof(uint32_t) +
           kinds.capacity() * sizeof(MoveKind) + locations.capacity() * sizeof(SourceLocation) +
           tools.capacity() * sizeof(ToolEvent);
}

ToolpathCollector::ToolpathCollector(ToolpathOptions options) : m_options(options) {
    setStart(Pose{});
}

void ToolpathCollector::setStart(const Pose& start) {
    m_position = finiteXyz(start) ? start : Pose{};
    m_data = ToolpathData{};
    addPoint(m_position.xyz(), false);
}

ToolpathData ToolpathCollector::take() {
    ToolpathData out = std::move(m_data);
    m_data = ToolpathData{};
    m_data.xInDiameter = out.xInDiameter;
    addPoint(m_position.xyz(), false);
    return out;
}

void ToolpathCollector::beginMove(const SourceLocation& location, MoveKind kind) {
    m_data.firstPoint.push_back(static_cast<uint32_t>(m_data.pointCount()));
    m_data.kinds.push_back(kind);
    m_data.locations.push_back(location);
}

void ToolpathCollector::addPoint(const Vec3& p, bool feed) {
    m_data.xyz.push_back(static_cast<float>(p.x()));
    m_data.xyz.push_back(static_cast<float>(p.y()));
    m_data.xyz.push_back(static_cast<float>(p.z()));
    m_data.bounds.add(p);
    if (feed) m_data.feedBounds.add(p);
}

void ToolpathCollector::addLine(const canon::Command& command, const Pose& target, MoveKind kind) {
    if (!finiteXyz(target)) {
        ++m_data.skippedMoves;
        return;
    }
    if (m_data.pointCount() + 1 > m_options.maxPoints) {
        m_data.truncated = true;
        return;
    }
    beginMove(command.location, kind);
    const Vec3 from = m_position.xyz();
    const Vec3 to = target.xyz();
    m_position = target;
    if (to == from) return;  // zero-length: the move exists (picking, highlight) but adds no point
    const bool feed = kind != MoveKind::Rapid;
    if (feed && m_data.feedBounds.empty) m_data.feedBounds.add(from);
    addPoint(to, feed);
}

void ToolpathCollector::consume(const canon::Command& command) {
    const canon::CommandBody& body = command.body;
    if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) {
        addLine(command, rapid->target, MoveKind::Rapid);
    } else if (const auto* line = std::get_if<canon::LinearMove>(&body)) {
        addLine(command, line->target, MoveKind::Feed);
    } else if (const auto* arc = std::get_if<canon::ArcMove>(&body)) {
        if (!finiteXyz(arc->target)) {
            ++m_data.skippedMoves;
            return;
        }
        m_scratch.clear();
        tessellateArc(m_position, *arc, m_options.arcChordToleranceMm, m_options.maxPointsPerArc,
                      m_scratch);
        if (m_data.pointCount() + m_scratch.size() > m_options.maxPoints) {
            m_data.truncated = true;
            return;
        }
        beginMove(command.location, MoveKind::Arc);
        if (m_data.feedBounds.empty) m_data.feedBounds.add(m_position.xyz());
        Vec3 last = m_position.xyz();
        for (const Vec3& p : m_scratch) {
            if (p == last) continue;
            addPoint(p, true);
            last = p;
        }
        m_position = arc->target;
    } else if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body)) {
        addLine(command, synced->target, MoveKind::Synced);
    } else if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) {
        addLine(command, probe->target, MoveKind::Probe);
    } else if (const auto* tool = std::get_if<canon::ToolChange>(&body)) {
        m_data.tools.push_back({static_cast<uint32_t>(m_data.moveCount()), *tool});
    } else if (const auto* update = std::get_if<canon::ToolUpdate>(&body)) {
        canon::ToolChange changed =
            m_data.tools.empty() ? canon::ToolChange{} : m_data.tools.back().tool;
        changed.geometry = update->geometry;
        changed.toolAxis = update->toolAxis;
        m_data.tools.push_back({static_cast<uint32_t>(m_data.moveCount()), std::move(changed)});
    } else if (const auto* stock = std::get_if<canon::StockDefinition>(&body)) {
        if (!m_data.stock) m_data.stock = *stock;
    } else if (const auto* mode = std::get_if<canon::DiameterMode>(&body)) {
        m_data.xInDiameter = mode->xInDiameter;
    }
}

}  // namespace kerf::graphics
