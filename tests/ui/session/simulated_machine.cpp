#include "simulated_machine.h"

#include "motion/runtime/machine_realtime_options.h"
#include "motion/runtime/realtime_motion_port.h"

namespace kerf::ui::test {

std::unique_ptr<task::MotionPort> connectSimulatedMachine(const machine::MachineConfig& config,
                                                          Reference reference) {
    motion::RealtimeOptions options = motion::machineRealtimeOptions(config);
    options.lockMemory = false;
    if (reference == Reference::Done) {
        // As after Home all and a move to the workpiece origin: the tool tip at 0 0 0.
        options.motion.startHomed = true;
        options.startPosition = {};
    }
    return std::make_unique<motion::RealtimeMotionPort>(config, options);
}

}  // namespace kerf::ui::test
