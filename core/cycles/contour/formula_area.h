#pragma once

#include <optional>
#include <vector>

#include "core/cycles/cycle_context.h"
#include "core/geometry/contour_region.h"

// The area of a contour formula (spec §8) level by level: a subcontour with its own DEPTH takes
// part only down to that depth (an island of the simple formula only below its top).
namespace kerf::cycles::contour {

// The machined area from the level above down to `bottom` (depth below the surface, > 0).
struct AreaLevel {
    double bottom = 0.0;
    Region area;
};

// The levels, shallowest first, each inside the one above it (the tool cannot reach below
// material it has not removed); levels with the same area are merged. `cycleDepth` (> 0) is
// cycle 20's depth, taken by the subcontours without DEPTH. Empty when nothing is machined.
std::vector<AreaLevel> formulaLevels(const ContourFormula& formula, double cycleDepth);

}  // namespace kerf::cycles::contour
