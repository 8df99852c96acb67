#pragma once

#include <optional>
#include <vector>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_values.h"

// Tool-axis levels shared by the drilling, tapping and thread cycles (spec 1.5, 1.6).
namespace kerf::cycles {

struct HoleLevels {
    double surface = 0.0;    // Q203
    double up = 1.0;         // +1: the tool axis points away from the material (negative depth)
    double clearance = 0.0;  // set-up clearance Q200 above the surface
    double top = 0.0;        // end height: Q203 + max(Q200, Q204)

    // The tool-axis coordinate `depth` (>= 0) into the material.
    double at(double depth) const { return surface - up * depth; }
};

// Levels for a depth parameter of the given sign (a positive depth inverts them).
HoleLevels holeLevels(const CycleValues& values, double depth);

// displayDepthErr: a positive depth is an error unless the machine allows it.
std::optional<CycleError> checkDepthSign(int cycle, uint16_t q, double depth,
                                         const CycleContext& context);

// Infeed end depths (positive, from the start of drilling) for a total depth: the first infeed,
// then each reduced by `decrement` but not below `minimum`; the last one ends at `total`. A
// plunging depth of 0 or beyond the total is a single infeed. Capped to keep loops bounded.
std::optional<CycleError> planInfeeds(int cycle, double total, double first, double decrement,
                                      double minimum, std::vector<double>& depths);

// Length of the tool's conical tip: R / tan(T-ANGLE / 2). Error if T-ANGLE is missing.
std::optional<CycleError> coneLength(int cycle, const ToolInfo& tool, double& length);

CycleError tooManyMoves(int cycle);

}  // namespace kerf::cycles
