#include "core/task/machine_status.h"

#include "core/base/translate_disambiguated.h"
#include "core/task/machine_state_name.h"

namespace kerf::task {

const char* machineStateName(MachineState state) {
    switch (state) {
        case MachineState::Idle:
            return KERF_TR_NOOP3("ready", "machine state");
        case MachineState::Running:
            return KERF_TR_NOOP3("running", "machine state");
        case MachineState::Held:
            return KERF_TR_NOOP3("feed hold", "machine state");
        case MachineState::Stopped:
            return KERF_TR_NOOP3("stopped", "machine state");
        case MachineState::Jogging:
            return KERF_TR_NOOP3("jogging", "machine state");
        case MachineState::Homing:
            return KERF_TR_NOOP3("homing", "machine state");
        case MachineState::Stopping:
            return KERF_TR_NOOP3("stopping", "machine state");
        case MachineState::EmergencyStop:
            return KERF_TR_NOOP3("emergency stop", "machine state");
        case MachineState::Fault:
            return KERF_TR_NOOP3("fault", "machine state");
        case MachineState::Offline:
            return KERF_TR_NOOP3("no machine", "machine state");
    }
    return "";
}

}  // namespace kerf::task
