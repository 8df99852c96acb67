#include "core/machine/machine_validation.h"

#include <initializer_list>

#include "core/machine/machine_schema.h"

namespace kerf::machine {

namespace {

class Validator {
public:
    Validator(std::string_view file, const KeyPositions& positions)
        : m_file(file), m_positions(positions) {}

    // Reports at the first of `keys` that has a position.
    template <typename... Args>
    void report(std::initializer_list<std::string_view> keys, const char* messageTemplate,
                Args&&... args) {
        TextPosition at;
        for (std::string_view key : keys) {
            auto it = m_positions.find(key);
            if (it != m_positions.end()) {
                at = it->second;
                break;
            }
        }
        m_diagnostics.push_back(Diagnostic::make(Severity::Error, "config", m_file, at.line,
                                                 at.column, messageTemplate,
                                                 std::forward<Args>(args)...));
    }

    void report(std::string_view key, Diagnostic d) {
        auto it = m_positions.find(key);
        d.file = m_file;
        if (it != m_positions.end()) {
            d.line = it->second.line;
            d.column = it->second.column;
        }
        m_diagnostics.push_back(std::move(d));
    }

    DiagnosticList take() { return std::move(m_diagnostics); }

private:
    std::string m_file;
    const KeyPositions& m_positions;
    DiagnosticList m_diagnostics;
};

std::string listLetters(std::string_view letters) {
    std::string out;
    for (char c : letters) {
        if (!out.empty()) out += ", ";
        out += c;
    }
    return out;
}

void checkRanges(const MachineConfig& config, Validator& v) {
    for (const std::string& key : parameterKeys(config)) {
        char letter = 0;
        const ParameterDescriptor* d = findParameter(key, &letter);
        Expected<ParameterValue> value = getParameter(config, key);
        if (!d || !value) continue;  // axes with invalid letters are reported separately
        const AxisConfig* axis = config.axis(letter);
        AxisType type = axis ? axis->type : AxisType::Linear;
        if (auto error = checkParameterValue(*d, key, *value, type)) v.report(key, *error);
    }
}

void checkAxis(const MachineConfig& config, const AxisConfig& axis, Validator& v) {
    auto key = [&axis](std::string_view name) { return axisParameterKey(axis.letter, name); };
    std::string table = std::string("axes.") + axis.letter;
    std::string minKey = key("min_limit");
    std::string maxKey = key("max_limit");
    std::string_view unit = axis.type == AxisType::Rotary ? "deg" : "mm";
    if (!(axis.minLimit < axis.maxLimit)) {
        v.report({minKey, maxKey, table}, KERF_TR_NOOP("{1} = {2} must be less than {3} = {4}"),
                 minKey, formatNumber(axis.minLimit), maxKey, formatNumber(axis.maxLimit));
    } else if (axis.homePosition < axis.minLimit || axis.homePosition > axis.maxLimit) {
        std::string homeKey = key("home");
        v.report({homeKey, minKey, maxKey, table},
                 KERF_TR_NOOP("{1} = {2} is outside the soft limits {3} … {4} {5}"), homeKey,
                 formatNumber(axis.homePosition), formatNumber(axis.minLimit),
                 formatNumber(axis.maxLimit), std::string(unit));
    }
    if (!axis.enabled && !axis.optional) {
        std::string enabledKey = key("enabled");
        v.report({enabledKey, table}, KERF_TR_NOOP("{1} = false is only allowed when {2} = true"),
                 enabledKey, key("optional"));
    }
    if (axis.diameterMode && (config.kind != MachineKind::Lathe || axis.type != AxisType::Linear)) {
        std::string diameterKey = key("diameter_mode");
        v.report({diameterKey, table},
                 KERF_TR_NOOP("{1} = true is only allowed on a linear axis of a lathe"),
                 diameterKey);
    }
}

void checkAxes(const MachineConfig& config, Validator& v) {
    if (config.axes.empty()) {
        v.report({}, KERF_TR_NOOP("the machine has no axes; add [axes.X] tables or start from a "
                                  "built-in machine with base = \"mill\""));
        return;
    }
    std::string seen;
    for (const AxisConfig& axis : config.axes) {
        std::string letter(1, axis.letter);
        if (!isAxisLetter(axis.letter)) {
            v.report({}, KERF_TR_NOOP("axis letter {1} is not one of {2}"), letter,
                     listLetters(axisLetters()));
            continue;
        }
        if (seen.find(axis.letter) != std::string::npos) {
            v.report({}, KERF_TR_NOOP("axis {1} is listed twice"), letter);
            continue;
        }
        seen += axis.letter;
        checkAxis(config, axis, v);
    }
}

void checkMachine(const MachineConfig& config, Validator& v) {
    std::string toolAxis = "\"" + std::string(1, config.toolAxis) + "\"";
    const AxisConfig* tool = config.axis(config.toolAxis);
    if (!config.axes.empty() && (!tool || !tool->enabled)) {
        v.report({"tool_axis"},
                 KERF_TR_NOOP("tool_axis = {1} is not an enabled axis of this machine ({2})"),
                 toolAxis, listLetters(config.enabledAxisLetters()));
    } else if (tool && tool->type != AxisType::Linear) {
        v.report({"tool_axis"}, KERF_TR_NOOP("tool_axis = {1} must be a linear axis"), toolAxis);
    }
    if (config.spindle.minRpm > config.spindle.maxRpm) {
        v.report({"spindle.min_rpm", "spindle.max_rpm"},
                 KERF_TR_NOOP("{1} = {2} must not exceed {3} = {4}"), "spindle.min_rpm",
                 std::to_string(config.spindle.minRpm), "spindle.max_rpm",
                 std::to_string(config.spindle.maxRpm));
    }
}

}  // namespace

DiagnosticList validateMachine(const MachineConfig& config, std::string_view file,
                               const KeyPositions& positions) {
    Validator v(file, positions);
    checkRanges(config, v);
    checkAxes(config, v);
    checkMachine(config, v);
    return v.take();
}

}  // namespace kerf::machine
