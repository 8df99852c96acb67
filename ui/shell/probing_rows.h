#pragma once

#include "ui/shell/machine_rows.h"

namespace kerf::ui {

// Manual probing in Manual operation (mill), as the TNC's probing functions: PROBING ROT (an
// edge's misalignment), POS (a datum in one axis), P (a corner) and CC (a circle centre); the
// direction key steps through X+ X- Y+ Y- Z-, the touch key probes from where the probe stands.
// When a function has its touches and the probe is back, dialogs show the result and, once
// the operator confirms, write it to row 0 of PRESET.PR (the datum, or the basic rotation).
SoftkeyRow probingRow(const MachineRowContext& context);

}  // namespace kerf::ui
