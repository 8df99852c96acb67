#include "core/machine/machine_validation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <string>

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
    if (axis.endless && axis.type != AxisType::Rotary) {
        std::string endlessKey = key("endless");
        v.report({endlessKey, table}, KERF_TR_NOOP("{1} = true is only allowed on a rotary axis"),
                 endlessKey);
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

// The axes of the kinematics must be rotary axes of the machine; the primary (tilting) axis of
// a two-axis kinematics turns about X or Y, and the secondary axis is another one.
void checkKinematics(const MachineConfig& config, Validator& v) {
    const KinematicsConfig& k = config.kinematics;
    if (k.type == KinematicsType::None) return;
    auto checkRotary = [&](const char* key, char letter) {
        const AxisConfig* axis = config.axis(letter);
        if (!axis || !axis->enabled || axis->type != AxisType::Rotary) {
            v.report({key, "kinematics.type"},
                     KERF_TR_NOOP("{1} = \"{2}\" is not an enabled rotary axis of this machine"),
                     key, std::string(1, letter));
            return false;
        }
        return true;
    };
    if (!checkRotary("kinematics.primary", k.primary)) return;
    if (k.type == KinematicsType::Table) return;
    if (!checkRotary("kinematics.secondary", k.secondary)) return;
    if (k.primary == 'C') {
        v.report({"kinematics.primary", "kinematics.type"},
                 KERF_TR_NOOP("kinematics.primary is the tilting axis: A or B, not C"));
    } else if (k.secondary == k.primary) {
        v.report({"kinematics.secondary", "kinematics.type"},
                 KERF_TR_NOOP("kinematics.secondary must be another axis than kinematics.primary"));
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
    const ProbeWorkpieceConfig& probe = config.probeWorkpiece;
    const std::array<std::array<double, 2>, 3> bounds{
        {{probe.xMinMm, probe.xMaxMm}, {probe.yMinMm, probe.yMaxMm}, {probe.zMinMm, probe.zMaxMm}}};
    for (size_t i = 0; i < bounds.size(); ++i) {
        if (!probe.enabled || bounds[i][0] < bounds[i][1]) continue;
        const std::string axis(1, "xyz"[i]);
        const std::string low = "simulation.probe." + axis + "_min";
        const std::string high = "simulation.probe." + axis + "_max";
        v.report({low, high}, KERF_TR_NOOP("{1} = {2} must be less than {3} = {4}"), low,
                 formatNumber(bounds[i][0]), high, formatNumber(bounds[i][1]));
    }
    const SimulationBlankConfig& blank = config.simulationBlank;
    const double blankBounds[3][2] = {
        {blank.minXMm, blank.maxXMm}, {blank.minYMm, blank.maxYMm}, {blank.minZMm, blank.maxZMm}};
    for (size_t i = 0; i < 3; ++i) {
        if (blankBounds[i][0] < blankBounds[i][1]) continue;
        const std::string axis(1, "xyz"[i]);
        const std::string low = "simulation.blank.min." + axis;
        const std::string high = "simulation.blank.max." + axis;
        v.report({low, high}, KERF_TR_NOOP("{1} = {2} must be less than {3} = {4}"), low,
                 formatNumber(blankBounds[i][0]), high, formatNumber(blankBounds[i][1]));
    }
    checkKinematics(config, v);
    if (config.bar.diameterMm > 0.0 && config.bar.boreDiameterMm >= config.bar.diameterMm) {
        v.report({"bar.bore_diameter", "bar.diameter"},
                 KERF_TR_NOOP("{1} = {2} must be smaller than {3} = {4}"), "bar.bore_diameter",
                 formatNumber(config.bar.boreDiameterMm), "bar.diameter",
                 formatNumber(config.bar.diameterMm));
    }
}

// The drive nodes in use: enabled axes and the spindle with a non-zero drive_node.
struct NodeUse {
    std::string key;
    int node = 0;
};

std::vector<NodeUse> driveNodes(const MachineConfig& config) {
    std::vector<NodeUse> nodes;
    for (const AxisConfig& axis : config.axes) {
        if (axis.enabled && axis.driveNode != 0) {
            nodes.push_back({axisParameterKey(axis.letter, "drive_node"), axis.driveNode});
        }
    }
    if (config.spindle.driveNode != 0)
        nodes.push_back({"spindle.drive_node", config.spindle.driveNode});
    return nodes;
}

// The CANopen rules apply once some drive has a node: unique node-IDs that are not the master's,
// a bus cycle that is a whole number of servo periods, a heartbeat timeout above the period, a
// CiA 301 bit rate and identities written as numbers.
void checkDrives(const MachineConfig& config, Validator& v) {
    std::vector<NodeUse> nodes = driveNodes(config);
    if (nodes.empty()) return;
    const DrivesConfig& d = config.drives;
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].node == d.masterNode) {
            v.report({nodes[i].key, "drives.master_node"},
                     KERF_TR_NOOP("{1} = {2} is the node-ID of drives.master_node"), nodes[i].key,
                     std::to_string(nodes[i].node));
        }
        for (size_t k = 0; k < i; ++k) {
            if (nodes[k].node == nodes[i].node) {
                v.report({nodes[i].key}, KERF_TR_NOOP("{1} = {2} is already the node of {3}"),
                         nodes[i].key, std::to_string(nodes[i].node), nodes[k].key);
            }
        }
    }
    double ratio = d.cyclePeriodMs / config.servoPeriodMs;
    if (ratio < 1.0 - 1e-9 || std::fabs(ratio - std::round(ratio)) > 1e-9) {
        v.report({"drives.cycle_period", "servo_period"},
                 KERF_TR_NOOP(
                     "drives.cycle_period = {1} must be a whole multiple of servo_period = {2}"),
                 formatNumber(d.cyclePeriodMs), formatNumber(config.servoPeriodMs));
    }
    if (d.heartbeatTimeoutMs <= d.heartbeatPeriodMs) {
        v.report({"drives.heartbeat_timeout", "drives.heartbeat_period"},
                 KERF_TR_NOOP(
                     "drives.heartbeat_timeout = {1} must exceed drives.heartbeat_period = {2}"),
                 std::to_string(d.heartbeatTimeoutMs), std::to_string(d.heartbeatPeriodMs));
    }
    constexpr int kRates[] = {10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000};
    if (std::find(std::begin(kRates), std::end(kRates), d.bitrate) == std::end(kRates)) {
        v.report(
            {"drives.bitrate"},
            KERF_TR_NOOP("drives.bitrate = {1} is not a CiA 301 bit rate (10000, 20000, 50000, "
                         "125000, 250000, 500000, 800000, 1000000)"),
            std::to_string(d.bitrate));
    }
    const std::pair<const char*, const std::string*> identities[] = {
        {"drives.vendor_id", &d.vendorId}, {"drives.product_code", &d.productCode}};
    for (const auto& [key, text] : identities) {
        if (!text->empty() && !parseDriveIdentity(*text)) {
            v.report({key}, KERF_TR_NOOP("{1} = \"{2}\" is not a 32-bit number such as 0x0000029C"),
                     std::string(key), *text);
        }
    }
}

}  // namespace

std::optional<uint32_t> parseDriveIdentity(std::string_view text) {
    bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
    std::string_view digits = hex ? text.substr(2) : text;
    if (digits.empty() || digits.size() > (hex ? 8u : 10u)) return std::nullopt;
    uint64_t value = 0;
    for (char c : digits) {
        int d = c >= '0' && c <= '9'          ? c - '0'
                : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                              : -1;
        if (d < 0) return std::nullopt;
        value = value * (hex ? 16u : 10u) + static_cast<uint64_t>(d);
    }
    if (value > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<uint32_t>(value);
}

DiagnosticList validateMachine(const MachineConfig& config, std::string_view file,
                               const KeyPositions& positions) {
    Validator v(file, positions);
    checkRanges(config, v);
    checkAxes(config, v);
    checkMachine(config, v);
    checkDrives(config, v);
    return v.take();
}

}  // namespace kerf::machine
