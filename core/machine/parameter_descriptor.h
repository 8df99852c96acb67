#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/base/expected.h"
#include "core/machine/axis_config.h"

namespace kerf::machine {

enum class ParameterType : uint8_t { Number, Integer, Bool, String, Enum };

// Machine parameters are keyed by their full TOML path ("spindle.max_rpm"); axis parameters exist
// once per axis under "axes.<letter>." and their descriptor key is the part after it.
enum class ParameterScope : uint8_t { Machine, Axis };

// A parameter value: Number -> double, Integer -> int64_t, Bool -> bool, String and Enum ->
// std::string (the enum's spelling in the file, e.g. "lathe").
using ParameterValue = std::variant<double, int64_t, bool, std::string>;

// Everything a loader, a writer or a settings screen needs to know about one parameter.
struct ParameterDescriptor {
    std::string_view key;
    ParameterScope scope = ParameterScope::Machine;
    ParameterType type = ParameterType::Number;
    std::string_view unit;        // empty when the value has no unit; linear axes for axis scope
    std::string_view rotaryUnit;  // axis scope: the unit on rotary axes
    ParameterValue defaultValue;  // rotary axes: axes A, B, C default to type "rotary"
    double minimum = 0.0;         // Number and Integer: allowed range, both ends included
    double maximum = 0.0;
    std::vector<std::string_view> enumValues;  // Enum: allowed spellings
    const char* description = "";              // one English line, marked with KERF_TR_NOOP
};

std::string_view parameterTypeName(ParameterType type);

// The unit of the parameter on an axis of this type ("mm/s" or "deg/s"); machine scope ignores it.
std::string_view parameterUnit(const ParameterDescriptor& descriptor,
                               AxisType axisType = AxisType::Linear);

// Shortest text that reads back to the same double, never in exponent form: "-5", "0.01".
std::string formatNumber(double value);

// A value as it is written in TOML: 0.01, 12000, true, "quoted \"text\"".
std::string formatParameterValue(const ParameterValue& value);

// What the parameter accepts, for messages and documentation: "1 … 100000 mm/s^2", "mill, lathe",
// "true, false"; empty for strings.
std::string formatAllowedValues(const ParameterDescriptor& descriptor,
                                AxisType axisType = AxisType::Linear);

// What a value of this parameter must be, for messages: "a number", "one of mill, lathe".
std::string expectedValueText(const ParameterDescriptor& descriptor);

// Checks type and range. `fullKey` names the parameter in the message. The diagnostic has no file
// position; the caller adds one when it has one.
MaybeError checkParameterValue(const ParameterDescriptor& descriptor, std::string_view fullKey,
                               const ParameterValue& value, AxisType axisType = AxisType::Linear);

}  // namespace kerf::machine
