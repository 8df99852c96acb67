#pragma once

#include <memory>

#include "core/machine/machine_config.h"
#include "core/task/motion_port.h"

namespace kerf::ui::test {

// The real-time machine on simulated drives, as app/main.cpp connects it (memory not locked).
// In a file of its own: motion's headers and Qt's `emit` keyword do not mix.
std::unique_ptr<task::MotionPort> connectSimulatedMachine(const machine::MachineConfig& config);

}  // namespace kerf::ui::test
