#pragma once

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_path.h"

// Where the SL cycles 21-25, 275 and 276 leave the tool (spec §1.6 item 7, machine parameter
// posAfterContPocket): up the tool axis to the clearance height only (ToolAxClearanceHeight),
// or from there back to the position before the cycle (PosBeforeMachining,
// CycleContext::slReturnToStart).
namespace kerf::cycles::contour {

// Up to `clearanceW` at `feed` (the tool axis only); with slReturnToStart then over the cycle's
// start in the plane and to its height, at rapid, the plane move at the higher of the two.
void finishSlCycle(CyclePath& path, const CycleContext& context, double clearanceW, double up,
                   const Feed& feed);

}  // namespace kerf::cycles::contour
