#include "motion/runtime/machine_realtime_options.h"

namespace kerf::motion {

RealtimeOptions machineRealtimeOptions(const machine::MachineConfig& config) {
    RealtimeOptions options;
    for (const machine::AxisConfig& axis : config.axes) {
        if (const auto a = axisFromLetter(axis.letter))
            options.motion.workOffset[static_cast<size_t>(axisIndex(*a))] = axis.presetPosition;
    }
    // RealtimeMachine makes the probe box from the machine file and this work offset.
    return options;
}

}  // namespace kerf::motion
