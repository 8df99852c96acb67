#pragma once

#include <functional>
#include <optional>

#include "core/canon/commands.h"
#include "core/machine/machine_config.h"
#include "core/machine/workpiece_frame.h"
#include "graphics/stock/cutter.h"
#include "graphics/stock/stock_simulation.h"

namespace kerf::tables {
class ToolTable;
}

namespace kerf::graphics {

// The mill cutter of a tool change: R and R2 of the canonical tool, the point angle (T-ANGLE)
// from `tools` (the canonical tool change does not carry it), and a touch probe's stylus, which
// removes nothing, for a tool with a TP_NO. The table's values are copied: the cutter may
// outlive the table. No table: flat or ball cutters only.
std::function<MillCutter(const canon::ToolChange&)> millCutterFromToolTable(
    const tables::ToolTable* tools);

// The stock simulation of a program on `machine`, the same for `kerf run --stock` and the test
// run: the machine's bar on a lathe, a blank derived from the path when the program has none,
// T-ANGLE from the tool table for a mill's drills (a lathe drill's point angle comes with its tool
// change), the turned workpiece of a machine with rotary tables.
StockOptions stockOptionsFor(const machine::MachineConfig& machine, const tables::ToolTable* tools,
                             std::optional<machine::WorkpieceFrame> workpieceFrame);

}  // namespace kerf::graphics
