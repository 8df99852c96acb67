#include "core/task/motion_port.h"

namespace kerf::task {

namespace {

bool submitAlone(MotionPort& motion, canon::CommandBody body) {
    if (!motion.drained()) return false;
    canon::Command command;
    command.body = std::move(body);
    if (!motion.submit(command)) return false;
    motion.flush();
    return true;
}

}  // namespace

bool MotionPort::manualSpindle(const canon::SpindleControl& spindle) {
    return submitAlone(*this, spindle);
}

bool MotionPort::manualCoolant(const canon::CoolantControl& coolant) {
    return submitAlone(*this, coolant);
}

MachineStatus MotionPort::status() const {
    MachineStatus status;
    const Progress now = progress();
    switch (now.state) {
        case State::Idle:
            status.state = MachineState::Idle;
            break;
        case State::Running:
            status.state = MachineState::Running;
            break;
        case State::Held:
            status.state = MachineState::Held;
            break;
        case State::Stopped:
            status.state = MachineState::Stopped;
            break;
        case State::Faulted:
            status.state = MachineState::Fault;
            break;
    }
    status.block = now.block;
    const Pose position = world().position;
    for (size_t i = 0; i < status.axes.size(); ++i) {
        AxisStatus& axis = status.axes[i];
        axis.nominal = axis.actual = axis.machineNominal = axis.machineActual = position.values[i];
    }
    return status;
}

}  // namespace kerf::task
