#pragma once

#include "core/cycles/pocket/milling_setup.h"

// The machining of the fixed pockets 251, 252, 253 and 254 (spec §4): the shape cleared from the
// inside out, depth by depth, then the walls finished (Q338 infeeds) and the floor. The clearing
// follows the shape's *core* (its centre line or arc; a point for a circle) and then rings, the
// shape offset inwards at equal stepovers of at most Q370 x R, each starting on the ray from the
// core's end through the shape's start, so one straight stepover leads from one to the next.
namespace kerf::cycles::pocket {

struct PocketShape {
    ClosedContour contour;   // finished size, local frame, counter-clockwise
    double halfWidth = 0.0;  // the inward offset at which the contour shrinks to its core
    PlanarSegment core;      // ends on the ray to contour.segments.front().start
    Placement placement;
    bool plungeAtCoreStart = false;  // 253, 254; else at the local origin (the pocket centre)
    bool returnToStart = true;       // 251-253 end at the start position in the plane
    // A straight move between two points of a convex region stays inside it; in a circular slot
    // the tool lifts above the workpiece before such a move.
    bool convex = true;
};

// Rounded rectangle, circle and slot (251-253): the core along the longer side.
PocketShape roundedPocket(double length, double width, double cornerRadius);

std::optional<CycleError> machinePocket(const MillingSetup& setup, const PocketShape& shape,
                                        CyclePath& path);

}  // namespace kerf::cycles::pocket
