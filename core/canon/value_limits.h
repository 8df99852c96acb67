#pragma once

#include <optional>

#include "core/canon/commands.h"

// The range of every number in the canonical stream. The interpreters refuse a command that leaves
// it (the block gets an error) and the motion planner refuses it again, so no infinite, NaN or
// absurdly large value can reach motion, whatever a program computes.
namespace kerf::canon {

// One bound in each quantity's own unit: mm (positions, centres, tool geometry, leads), degrees
// (rotary axes, spindle angles), mm/min or mm/rev (feeds), rpm, m/min, seconds (dwell) and
// radians (arc sweeps). A kilometre of travel, 1000 m/min or 11 days of dwell is far beyond any
// machine, and every double below it keeps micrometre resolution.
inline constexpr double kMaxStreamMagnitude = 1.0e6;

struct UnsafeValue {
    const char* quantity = "";  // "X", "feed", "arc centre Y", "dwell time" ...
    double value = 0.0;
};

// The first number of the command that is not finite or beyond kMaxStreamMagnitude.
std::optional<UnsafeValue> findUnsafeValue(const CommandBody& body);

}  // namespace kerf::canon
