#pragma once

#include "core/interp/program_status.h"
#include "core/task/machine_status.h"

namespace kerf::ui {

// The program's status with the spindle and the coolant as the machine has them now: once no
// program moves the machine, the operator's keys (spindle on/off, coolant on/off) and a Stop
// change them, and the PGM tab's M functions (M3/M4/M5, M7/M8/M9) and the speed of a turning
// spindle follow.
// The direction of a turning spindle is read from the sign of its actual speed (M4: negative);
// a coolant the program switched on with M7 stays M7.
interp::ProgramStatus withMachineSpindleAndCoolant(interp::ProgramStatus status,
                                                   const task::MachineStatus& machine);

}  // namespace kerf::ui
