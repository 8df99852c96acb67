#include "motion/runtime/machine_realtime_options.h"

namespace kerf::motion {

RealtimeOptions machineRealtimeOptions(const machine::MachineConfig& config) {
    RealtimeOptions options;
    for (const machine::AxisConfig& axis : config.axes) {
        if (const auto a = axisFromLetter(axis.letter)) {
            const auto i = static_cast<size_t>(axisIndex(*a));
            options.motion.workOffset[i] = axis.presetPosition;
            // Power-on: the axes stand at their reference points (machine coordinates), without
            // a tool; the tip position is in workpiece coordinates.
            options.startPosition[i] = axis.homePosition - axis.presetPosition;
        }
    }
    // The axes are not referenced until Home all, unless the machine file says it needs none.
    options.motion.startHomed = !config.referenceRequired;
    // RealtimeMachine makes the probe box from the machine file and this work offset.
    return options;
}

}  // namespace kerf::motion
