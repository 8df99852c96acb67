#pragma once

#include <memory>

#include "core/machine/machine_config.h"
#include "core/task/motion_port.h"

namespace kerf::ui::test {

enum class Reference { Done, Required };

// The real-time machine on simulated drives, as app/main.cpp connects it (memory not locked).
// Reference::Done: the axes count as homed from the start and the tool tip stands at the
// workpiece origin, as after Home all and a move there, so that tests of programs need no
// reference run; Reference::Required: as the machine file says (app/main.cpp).
// In a file of its own: motion's headers and Qt's `emit` keyword do not mix.
std::unique_ptr<task::MotionPort> connectSimulatedMachine(const machine::MachineConfig& config,
                                                          Reference reference = Reference::Done);

}  // namespace kerf::ui::test
