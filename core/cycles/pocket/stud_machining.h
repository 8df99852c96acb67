#pragma once

#include "core/cycles/pocket/milling_setup.h"

// The machining of the studs 256 and 257 (spec §4): from a start point beside the blank, at each
// depth, contour-parallel passes round the stud from the blank inwards at a stepover of at most
// Q370 x R, the first approached on a quarter arc, the last left on one; then the walls finished
// (Q338 infeeds) and the floor. The cycle ends above the last point, in the tool axis only.
namespace kerf::cycles::pocket {

struct StudShape {
    ClosedContour stud;   // finished size, counter-clockwise, local frame, starting at +u
    double margin = 0.0;  // farthest distance from the stud (plus allowance) to the blank
    Placement placement;  // rotation and centre; the passes start on the local +u axis
    // Cycle 256's Q437 1-4: the start point beside a corner of the blank (local frame); the
    // passes then start where they come nearest to it, so the stepovers spiral in along one ray.
    std::optional<Vec2> startCorner;
};

// The start point beside the blank: the tool's edge this far from the blank (spec: "2 mm").
inline constexpr double kBesideBlankMm = 2.0;

std::optional<CycleError> machineStud(const MillingSetup& setup, const StudShape& shape,
                                      CyclePath& path);

}  // namespace kerf::cycles::pocket
