#pragma once

#include "ui/shell/machine_rows.h"

namespace kerf::ui {

// Electronic handwheel (simulated): choose the axis and the step factor, turn by one detent
// either way.
SoftkeyRow handwheelRow(const MachineRowContext& context);

// Spindle, coolant, set a preset by entry and, on a lathe, tool calibration (Manual operation
// and Electronic handwheel).
SoftkeyRow manualFunctionsRow(const MachineRowContext& context);

}  // namespace kerf::ui
