#pragma once

// The machine-parameter schema: the single list of parameters that loading, checking, writing and
// the settings screen are driven from. Keys are TOML paths: "rapid_velocity", "spindle.max_rpm",
// "axes.X.max_velocity".

#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"
#include "core/machine/machine_config.h"
#include "core/machine/parameter_descriptor.h"

namespace kerf::machine {

// Machine-wide parameters, in the order files and screens show them.
const std::vector<ParameterDescriptor>& machineParameters();

// Parameters every axis has; their keys are relative to "axes.<letter>.".
const std::vector<ParameterDescriptor>& axisParameters();

// "axes.X.max_velocity" from 'X' and "max_velocity".
std::string axisParameterKey(char letter, std::string_view axisKey);

// The descriptor of a full key, or nullptr. For axis keys the letter must be an axis letter (it
// need not be an axis of any machine); it is stored in *axisLetter when that is given.
const ParameterDescriptor* findParameter(std::string_view fullKey, char* axisLetter = nullptr);

// Every full key of this machine: the machine parameters, then each axis's parameters.
std::vector<std::string> parameterKeys(const MachineConfig& config);

// Reads a parameter by full key. Fails for unknown keys and axes the machine does not have.
Expected<ParameterValue> getParameter(const MachineConfig& config, std::string_view fullKey);

// Writes a parameter after checking its type and range (an integer is accepted for a number).
// Rules that relate several parameters are checked by validateMachine().
MaybeError setParameter(MachineConfig& config, std::string_view fullKey,
                        const ParameterValue& value);

}  // namespace kerf::machine
