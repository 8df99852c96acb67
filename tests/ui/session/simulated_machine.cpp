#include "simulated_machine.h"

#include "motion/runtime/machine_realtime_options.h"
#include "motion/runtime/realtime_motion_port.h"

namespace kerf::ui::test {

std::unique_ptr<task::MotionPort> connectSimulatedMachine(const machine::MachineConfig& config) {
    motion::RealtimeOptions options = motion::machineRealtimeOptions(config);
    options.lockMemory = false;
    return std::make_unique<motion::RealtimeMotionPort>(config, options);
}

}  // namespace kerf::ui::test
