#pragma once

#include "core/task/operating_mode.h"

namespace kerf::ui {

// The operating modes as the FAGOR 8035 T names them (its OPMODE table, spec part 2 §5.15):
// JOG, Electronic handwheel, MDI, Single-block execution, Automatic execution, Editing,
// Simulation. English, translated in the "kerf" context.
const char* fagorMachineModeName(task::MachineMode mode);
const char* fagorProgrammingModeName(task::ProgrammingMode mode);

}  // namespace kerf::ui
