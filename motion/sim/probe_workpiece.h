#pragma once

#include <functional>

#include "core/machine/machine_config.h"
#include "motion/kinematics/machine_model.h"

namespace kerf::motion {

// The machine file's simulated probe workpiece ([simulation.probe], a box in machine coordinates
// of the tool tip) as a test on the tip in workpiece coordinates, which are the machine's minus
// `workOffset`. Empty when the machine file enables none.
std::function<bool(const AxisVector& tip)> probeWorkpiece(const machine::MachineConfig& config,
                                                          const AxisVector& workOffset);

}  // namespace kerf::motion
