#pragma once

#include "core/cycles/pocket/milling_setup.h"

// The machining of the fixed pockets 251, 252 and 253 (spec §4): a rounded rectangle (a circle
// when both sides are twice the corner radius, a slot when the radius is half the width) cleared
// from the inside out with contour-parallel offsets at a stepover of at most Q370 x R, depth by
// depth, then the walls finished (Q338 infeeds) and the floor.
namespace kerf::cycles::pocket {

struct PocketShape {
    double length = 0.0;  // along the local u axis
    double width = 0.0;
    double cornerRadius = 0.0;
    Placement placement;
    bool plungeAtSlotEnd = false;  // 253: plunge at the centre of the left arc, else the centre
    bool returnToStart = true;     // 251/252/253 end at the start position in the plane
};

std::optional<CycleError> machinePocket(const MillingSetup& setup, const PocketShape& shape,
                                        CyclePath& path);

}  // namespace kerf::cycles::pocket
