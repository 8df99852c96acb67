#include "core/task/machine_status.h"

#include "core/base/translate.h"

namespace kerf::task {

const char* machineStateName(MachineState state) {
    switch (state) {
        case MachineState::Idle:
            return KERF_TR_NOOP("ready");
        case MachineState::Running:
            return KERF_TR_NOOP("running");
        case MachineState::Held:
            return KERF_TR_NOOP("feed hold");
        case MachineState::Stopped:
            return KERF_TR_NOOP("stopped");
        case MachineState::Jogging:
            return KERF_TR_NOOP("jogging");
        case MachineState::Homing:
            return KERF_TR_NOOP("homing");
        case MachineState::Stopping:
            return KERF_TR_NOOP("stopping");
        case MachineState::EmergencyStop:
            return KERF_TR_NOOP("emergency stop");
        case MachineState::Fault:
            return KERF_TR_NOOP("fault");
        case MachineState::Offline:
            return KERF_TR_NOOP("no machine");
    }
    return "";
}

}  // namespace kerf::task
