#include "ui/session/program_origin.h"

namespace kerf::ui {

Pose machineFilePreset(const machine::MachineConfig& machine) {
    Pose preset;
    for (const machine::AxisConfig& config : machine.axes) {
        if (const auto axis = axisFromLetter(config.letter)) preset[*axis] = config.presetPosition;
    }
    return preset;
}

Pose programOrigin(const machine::MachineConfig& machine, const task::PresetStore& presets,
                   const Pose& shift) {
    Pose origin = machineFilePreset(machine);
    for (size_t i = 0; i < origin.values.size(); ++i)
        origin.values[i] += shift.values[i];
    if (machine.kind == machine::MachineKind::Lathe) return origin;
    const auto row0 = presets.read();
    for (const machine::AxisConfig& config : machine.axes) {
        const auto axis = axisFromLetter(config.letter);
        if (!axis) continue;
        if (const auto value = row0[static_cast<size_t>(axisIndex(*axis))]) origin[*axis] = *value;
    }
    return origin;
}

}  // namespace kerf::ui
