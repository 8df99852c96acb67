#include "core/machine/parameter_descriptor.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace kerf::machine {

namespace {

Diagnostic configError(std::string messageTemplate, std::string a1, std::string a2,
                       std::string a3) {
    return Diagnostic::make(Severity::Error, "config", "", 0, 0, std::move(messageTemplate),
                            std::move(a1), std::move(a2), std::move(a3));
}

bool typeMatches(ParameterType type, const ParameterValue& value) {
    switch (type) {
        case ParameterType::Number:
            return std::holds_alternative<double>(value) || std::holds_alternative<int64_t>(value);
        case ParameterType::Integer:
            return std::holds_alternative<int64_t>(value);
        case ParameterType::Bool:
            return std::holds_alternative<bool>(value);
        case ParameterType::String:
        case ParameterType::Enum:
            return std::holds_alternative<std::string>(value);
    }
    return false;
}

}  // namespace

std::string expectedValueText(const ParameterDescriptor& d) {
    switch (d.type) {
        case ParameterType::Number:
            return "a number";
        case ParameterType::Integer:
            return "an integer";
        case ParameterType::Bool:
            return "true or false";
        case ParameterType::String:
            return "a string";
        case ParameterType::Enum:
            return "one of " + formatAllowedValues(d);
    }
    return "a value";
}

std::string_view parameterTypeName(ParameterType type) {
    switch (type) {
        case ParameterType::Number:
            return "number";
        case ParameterType::Integer:
            return "integer";
        case ParameterType::Bool:
            return "bool";
        case ParameterType::String:
            return "string";
        case ParameterType::Enum:
            return "enum";
    }
    return "number";
}

std::string_view parameterUnit(const ParameterDescriptor& descriptor, AxisType axisType) {
    bool rotary = descriptor.scope == ParameterScope::Axis && axisType == AxisType::Rotary;
    return rotary ? descriptor.rotaryUnit : descriptor.unit;
}

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
    if (value == 0.0) return "0";  // also for -0.0
    // Without a precision the text is the shortest that reads back exactly; fixed notation
    // unless that would be a long row of digits (1e300 in a diagnostic).
    const double magnitude = std::fabs(value);
    const auto format = magnitude >= 1e15 || magnitude < 1e-6 ? std::chars_format::scientific
                                                              : std::chars_format::fixed;
    std::array<char, 400> buffer{};
    auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, format);
    return std::string(buffer.data(), result.ptr);
}

std::string formatParameterValue(const ParameterValue& value) {
    if (const auto* number = std::get_if<double>(&value)) return formatNumber(*number);
    if (const auto* integer = std::get_if<int64_t>(&value)) return std::to_string(*integer);
    if (const auto* flag = std::get_if<bool>(&value)) return *flag ? "true" : "false";
    // A TOML basic string.
    std::string out = "\"";
    for (char c : std::get<std::string>(value)) {
        auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (byte < 0x20 || byte == 0x7f) {
            constexpr std::string_view hex = "0123456789ABCDEF";
            out += "\\u00";
            out += hex[byte >> 4];
            out += hex[byte & 0xf];
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string formatAllowedValues(const ParameterDescriptor& descriptor, AxisType axisType) {
    switch (descriptor.type) {
        case ParameterType::Number:
        case ParameterType::Integer: {
            std::string out =
                formatNumber(descriptor.minimum) + " … " + formatNumber(descriptor.maximum);
            std::string_view unit = parameterUnit(descriptor, axisType);
            if (!unit.empty()) {
                out += ' ';
                out += unit;
            }
            return out;
        }
        case ParameterType::Bool:
            return "true, false";
        case ParameterType::String:
            return "";
        case ParameterType::Enum: {
            std::string out;
            for (std::string_view v : descriptor.enumValues) {
                if (!out.empty()) out += ", ";
                out += v;
            }
            return out;
        }
    }
    return "";
}

MaybeError checkParameterValue(const ParameterDescriptor& descriptor, std::string_view fullKey,
                               const ParameterValue& value, AxisType axisType) {
    std::string key(fullKey);
    if (!typeMatches(descriptor.type, value)) {
        return configError(KERF_TR_NOOP("{1} = {2} has the wrong type; expected {3}"), key,
                           formatParameterValue(value), expectedValueText(descriptor));
    }
    if (descriptor.type == ParameterType::Number || descriptor.type == ParameterType::Integer) {
        double number = std::holds_alternative<double>(value)
                            ? std::get<double>(value)
                            : static_cast<double>(std::get<int64_t>(value));
        // Written so that NaN fails too.
        if (!(number >= descriptor.minimum && number <= descriptor.maximum)) {
            return configError(KERF_TR_NOOP("{1} = {2} is outside the allowed range {3}"), key,
                               formatParameterValue(value),
                               formatAllowedValues(descriptor, axisType));
        }
    }
    if (descriptor.type == ParameterType::Enum) {
        const std::string& text = std::get<std::string>(value);
        if (std::find(descriptor.enumValues.begin(), descriptor.enumValues.end(), text) ==
            descriptor.enumValues.end()) {
            return configError(KERF_TR_NOOP("{1} = {2} is not one of {3}"), key,
                               formatParameterValue(value), formatAllowedValues(descriptor));
        }
    }
    return std::nullopt;
}

}  // namespace kerf::machine
