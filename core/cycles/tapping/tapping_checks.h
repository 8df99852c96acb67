#pragma once

#include <optional>

#include "core/cycles/cycle_context.h"

namespace kerf::cycles {

// The tool table's PITCH, when set, must match the cycle's thread pitch (spec §3).
std::optional<CycleError> checkToolPitch(int cycle, const ToolInfo& tool, double pitch);
// A thread pitch of 0 cannot be cut.
std::optional<CycleError> checkPitchNotZero(int cycle, uint16_t q, double pitch);
// Spindle angle after travelling `distance` with `lead` per revolution from `startDeg`.
double spindleAngleAfter(double startDeg, double distance, double lead);

}  // namespace kerf::cycles
