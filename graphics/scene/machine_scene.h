#pragma once

#include "core/machine/machine_config.h"
#include "graphics/scene/scene.h"

namespace kerf::graphics {

// The scene of a machine: mill or lathe, and its soft limits (the enabled X, Y, Z axes) as the
// limits box.
SceneOptions sceneOptionsFor(const machine::MachineConfig& machine);

}  // namespace kerf::graphics
