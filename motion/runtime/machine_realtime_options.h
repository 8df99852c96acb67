#pragma once

#include "core/machine/machine_config.h"
#include "motion/runtime/realtime_machine.h"

namespace kerf::motion {

// The real-time machine's options as the machine file gives them: the workpiece origin from the
// axes' `preset` (motion's work offset) and, on simulated drives, the [simulation.probe] box.
RealtimeOptions machineRealtimeOptions(const machine::MachineConfig& config);

}  // namespace kerf::motion
