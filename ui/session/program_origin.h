#pragma once

#include "core/geometry/axes.h"
#include "core/machine/machine_config.h"
#include "core/task/preset_store.h"

namespace kerf::ui {

// The workpiece origin a program starts from, machine coordinates: the machine file's preset
// moved by `shift` (the operator's entries), and on a mill every axis row 0 of PRESET.PR sets
// (a lathe's origins are the FAGOR zero offsets instead). Program run and the test run (with or
// without a machine) take their origin from here.
Pose programOrigin(const machine::MachineConfig& machine, const task::PresetStore& presets,
                   const Pose& shift = {});

// The machine file's preset of every axis, machine coordinates.
Pose machineFilePreset(const machine::MachineConfig& machine);

}  // namespace kerf::ui
