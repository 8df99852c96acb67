#pragma once

#include <optional>
#include <string>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_parameter.h"

namespace kerf::cycles {

// The checks of a cycle parameter that need no machine state: the interpreter makes them when
// it runs a definition and `kerf check` makes them on literal values before the run, so that
// both report the same problem in the same words.

// "Q200", or the keyword of an old-style word.
std::string parameterName(const ParameterDescriptor& d);

// `d` is not written in the block of `owner` ("cycle 200"); none when it may be missing
// (added by a later software: the default is taken).
std::optional<CycleError> missingParameterError(const std::string& owner,
                                                const ParameterDescriptor& d);

// `value` (as written, in program units) is outside the range of `d` or not a whole number
// where one is required.
std::optional<CycleError> parameterValueError(const std::string& owner,
                                              const ParameterDescriptor& d, double value);

}  // namespace kerf::cycles
