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
    return (xyz.capacity() + toolAxis.capacity()) * sizeof(float) +
           firstPoint.capacity() * sizeof(uint32_t) + kinds.capacity() * sizeof(MoveKind) +
           locations.capacity() * sizeof(SourceLocation) + tools.capacity() * sizeof(ToolEvent);
}

ToolpathCollector::ToolpathCollector(ToolpathOptions options) : m_options(options) {
    setStart(Pose{});
}

void ToolpathCollector::setStart(const Pose& start) {
    m_position = finiteXyz(start) ? start : Pose{};
    m_data = ToolpathData{};
    addPoint(onPart(m_position), false);
}

ToolpathData ToolpathCollector::take() {
    ToolpathData out = std::move(m_data);
    m_data = ToolpathData{};
    m_data.xInDiameter = out.xInDiameter;
    addPoint(onPart(m_position), false);
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

machine::ToolOnPart ToolpathCollector::onPart(const Pose& stream) const {
    if (m_options.workpieceFrame) return m_options.workpieceFrame->toPart(stream);
    return {stream.xyz(), Vec3::UnitZ()};
}

void ToolpathCollector::addPoint(const machine::ToolOnPart& p, bool feed) {
    addPoint(p.tip, feed);
    if (!m_options.workpieceFrame) return;
    for (int k = 0; k < 3; ++k)
        m_data.toolAxis.push_back(static_cast<float>(p.axis[k]));
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
    if (m_options.workpieceFrame) {
        m_samples.clear();
        m_options.workpieceFrame->sample(m_position, target, m_options.maxTableStepDeg, m_samples);
        if (m_data.pointCount() + m_samples.size() > m_options.maxPoints) {
            m_data.truncated = true;
            return;
        }
    }
    beginMove(command.location, kind);
    const Pose from = m_position;
    m_position = target;
    const bool feed = kind != MoveKind::Rapid;
    if (!m_options.workpieceFrame) {
        if (target.xyz() == from.xyz()) return;  // zero-length: the move exists but adds no point
        if (feed && m_data.feedBounds.empty) m_data.feedBounds.add(from.xyz());
        addPoint(target.xyz(), feed);
        return;
    }
    Vec3 last = onPart(from).tip;
    if (feed && m_data.feedBounds.empty) m_data.feedBounds.add(last);
    for (const machine::ToolOnPart& p : m_samples) {
        if (p.tip == last) continue;
        addPoint(p, feed);
        last = p.tip;
    }
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
        Pose at = m_position;
        Vec3 last = onPart(at).tip;
        if (m_data.feedBounds.empty) m_data.feedBounds.add(last);
        for (const Vec3& p : m_scratch) {
            at.setXyz(p);  // arcs keep the tables still: one turn maps every chord
            const machine::ToolOnPart on = onPart(at);
            if (on.tip == last) continue;
            addPoint(on, true);
            last = on.tip;
        }
        m_position = arc->target;
    } else if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body)) {
        addLine(command, synced->target, MoveKind::Synced);
    } else if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) {
        addLine(command, probe->target, MoveKind::Probe);
    } else if (const auto* tool = std::get_if<canon::ToolChange>(&body)) {
        if (m_options.workpieceFrame)
            m_options.workpieceFrame->setToolLength(tool->geometry.lengthMm);
        m_data.tools.push_back({static_cast<uint32_t>(m_data.moveCount()), *tool});
    } else if (const auto* update = std::get_if<canon::ToolUpdate>(&body)) {
        if (m_options.workpieceFrame)
            m_options.workpieceFrame->setToolLength(update->geometry.lengthMm);
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
