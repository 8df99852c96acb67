#pragma once

#include <optional>
#include <vector>

#include "core/canon/commands.h"

namespace kerf::task {

// Mid-program start: the program is interpreted from its beginning while BlockScan swallows the
// commands before the chosen block and remembers the state they leave (tool, spindle, coolant,
// feed mode, position). At the chosen block it hands out the commands that restore that state
// and approach the block's start point, then lets everything through.
class BlockScan {
public:
    BlockScan(uint32_t fileId, uint32_t line) : m_fileId(fileId), m_line(line) {}

    // True once the chosen block has been reached (the command is then passed on).
    bool reached() const { return m_reached; }
    // Feeds one command of the scan; returns true if it belongs to the chosen block or later.
    bool consume(const canon::Command& command);
    // The commands that restore the state (tool, tolerance, feed mode, spindle, coolant) and then
    // approach the block's start point from `current` (the machine's position): in the tool axis
    // first when moving up, last when moving down.
    std::vector<canon::Command> restore(const Pose& current, Axis toolAxis) const;
    const Pose& position() const { return m_position; }

private:
    uint32_t m_fileId;
    uint32_t m_line;
    bool m_reached = false;
    Pose m_position{};
    std::optional<canon::ToolChange> m_tool;
    std::optional<canon::SpindleControl> m_spindle;
    std::optional<canon::CoolantControl> m_coolant;
    canon::FeedMode m_feedMode = canon::FeedMode::PerMinute;
    std::optional<canon::PathTolerance> m_tolerance;
    SourceLocation m_at;
};

}  // namespace kerf::task
