#pragma once

#include <optional>
#include <string>

#include "core/geometry/axes.h"
#include "core/machine/machine_config.h"

namespace kerf::app {

// Where the workpiece origin lies in machine coordinates: each axis's `preset` from the machine
// file, replaced on the axes --work-offset names ("Z-300" keeps the file's X and Y). A malformed
// option (main() refuses it) changes nothing.
Pose workpieceOrigin(const machine::MachineConfig& machine,
                     const std::optional<std::string>& workOffsetOption);

}  // namespace kerf::app
