#pragma once

#include <optional>
#include <string>

#include "core/geometry/axes.h"
#include "core/machine/machine_config.h"
#include "core/tables/preset_table.h"

namespace kerf::app {

// Where the workpiece origin lies in machine coordinates: each axis's `preset` from the machine
// file, replaced by the axes a preset row (--preset) has values for, then on the axes
// --work-offset names ("Z-300" keeps the others). A malformed option (main() refuses it)
// changes nothing.
Pose workpieceOrigin(const machine::MachineConfig& machine,
                     const std::optional<std::string>& workOffsetOption,
                     const tables::PresetData* presetRow = nullptr);

}  // namespace kerf::app
