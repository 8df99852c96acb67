#pragma once

#include <vector>

#include "core/canon/commands.h"
#include "core/machine/machine_config.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {

// The blank the simulation clamps for a milling program without BLK FORM ([simulation.blank]),
// in workpiece coordinates of the machine file's preset.
canon::StockDefinition simulationBlank(const machine::MachineConfig& machine);

// Where the machine file's preset (axes.<L>.preset, the default blank's origin) lies in
// workpiece coordinates of a run whose preset is `presetInMachine`.
Vec3 machineFilePresetIn(const machine::MachineConfig& machine, const Pose& presetInMachine);

// The part the touch probe touches: the blank's solids and the calibration sphere, placed with
// the machine's [simulation.setup]; `origin` is where the blank's programmed origin lies in the
// coordinates of the touches. Without a machine: the blank exactly where it was programmed.
SimulatedWorkpiece simulatedPart(const machine::MachineConfig* machine,
                                 const std::vector<Solid>& blank, const Vec3& origin);

}  // namespace kerf::workpiece
