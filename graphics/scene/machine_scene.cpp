#include "graphics/scene/machine_scene.h"

#include <string>

namespace kerf::graphics {

SceneOptions sceneOptionsFor(const machine::MachineConfig& machine) {
    SceneOptions options;
    options.lathe = machine.kind == machine::MachineKind::Lathe;
    Bounds3 limits;
    for (char letter : std::string("XYZ")) {
        const machine::AxisConfig* axis = machine.axis(letter);
        if (axis == nullptr || !axis->enabled) continue;
        const auto index = static_cast<Eigen::Index>(letter - 'X');
        Vec3 lo(0, 0, 0);
        Vec3 hi(0, 0, 0);
        lo[index] = axis->minLimit;
        hi[index] = axis->maxLimit;
        limits.add(lo);
        limits.add(hi);
    }
    if (!limits.empty) options.limits = limits;
    return options;
}

}  // namespace kerf::graphics
