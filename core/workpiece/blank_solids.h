#pragma once

#include <vector>

#include "core/canon/commands.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {

// The solids of a program's blank (BLK FORM), in its programmed position: a box, or a cylinder
// about Z from DIST down by its length, a tube's bore a cavity through it. A cylinder about
// another axis gives none (the simulated part works with the tool axis along Z).
std::vector<Solid> blankSolids(const canon::StockDefinition& stock);

}  // namespace kerf::workpiece
