#pragma once

#include <span>

#include "core/cycles/cycle_descriptor.h"
#include "core/cycles/global_def.h"

namespace kerf::cycles {

// The catalogue of implemented cycles, in number order. It drives the interpreter (what runs,
// DEF or CALL active, parameter checks) and will generate the HMI's cycle dialogs.
std::span<const CycleDescriptor* const> allCycles();
const CycleDescriptor* findCycle(int number);

// Checks a value against a parameter's range; the message names the cycle and the parameter.
std::optional<CycleError> checkParameter(const CycleDescriptor& cycle,
                                         const ParameterDescriptor& parameter, double value);

}  // namespace kerf::cycles
