#include "core/task/block_scan.h"

namespace kerf::task {

bool BlockScan::consume(const canon::Command& command) {
    if (m_reached) return true;
    const SourceLocation& at = command.location;
    if (at.fileId == m_fileId && at.line >= m_line) {
        m_reached = true;
        m_at = at;
        return true;
    }
    const canon::CommandBody& body = command.body;
    if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) {
        m_position = rapid->target;
    } else if (const auto* line = std::get_if<canon::LinearMove>(&body)) {
        m_position = line->target;
    } else if (const auto* arc = std::get_if<canon::ArcMove>(&body)) {
        m_position = arc->target;
    } else if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body)) {
        m_position = synced->target;
    } else if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) {
        m_position = probe->target;
    } else if (const auto* tool = std::get_if<canon::ToolChange>(&body)) {
        m_tool = *tool;
    } else if (const auto* update = std::get_if<canon::ToolUpdate>(&body)) {
        if (m_tool) {
            m_tool->geometry = update->geometry;
            m_tool->toolAxis = update->toolAxis;
        }
    } else if (const auto* spindle = std::get_if<canon::SpindleControl>(&body)) {
        m_spindle = *spindle;
    } else if (const auto* coolant = std::get_if<canon::CoolantControl>(&body)) {
        m_coolant = *coolant;
    } else if (const auto* mode = std::get_if<canon::SetFeedMode>(&body)) {
        m_feedMode = mode->mode;
    } else if (const auto* tolerance = std::get_if<canon::PathTolerance>(&body)) {
        m_tolerance = *tolerance;
    }
    return false;
}

std::vector<canon::Command> BlockScan::restore(const Pose& current, Axis toolAxis) const {
    std::vector<canon::Command> out;
    auto add = [&](canon::CommandBody body) {
        out.push_back(canon::Command{m_at, std::move(body)});
    };
    if (m_tool) add(*m_tool);
    if (m_tolerance) add(*m_tolerance);
    if (m_feedMode != canon::FeedMode::PerMinute) add(canon::SetFeedMode{m_feedMode});
    // The spindle and coolant run before the tool moves towards the part.
    if (m_spindle) add(*m_spindle);
    if (m_coolant) add(*m_coolant);
    // Approach the block's start point: up in the tool axis first, down last.
    Pose via = current;
    if (m_position[toolAxis] > current[toolAxis]) {
        via[toolAxis] = m_position[toolAxis];
        add(canon::RapidMove{via});
    }
    Pose above = m_position;
    above[toolAxis] = via[toolAxis];
    add(canon::RapidMove{above});
    if (!(above == m_position)) add(canon::RapidMove{m_position});
    return out;
}

}  // namespace kerf::task
