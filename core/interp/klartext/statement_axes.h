#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "core/geometry/axes.h"
#include "core/interp/klartext/statements.h"

namespace kerf::klartext {

// The first axis a motion block programs that is not in `machineAxes` (an `L A+90` on a three-axis
// mill): the control cannot move it, so the block is an error rather than a move without it.
std::optional<Axis> axisMissingFrom(const Statement& statement, AxisMask machineAxes);

// The 1-based column of the word for `axis` in a block's text ("A+90", "IA+5", "AQ1"), or 1.
uint32_t columnOfAxisWord(std::string_view text, Axis axis);

}  // namespace kerf::klartext
