#include "core/machine/machine_loader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "core/base/atomic_file.h"
#include "core/machine/builtin_machines.h"
#include "core/machine/detail/closest_key.h"
#include "core/machine/machine_schema.h"
#include "core/machine/machine_validation.h"

namespace kerf::machine {

namespace {

TextPosition positionOf(const toml::source_region& region) {
    return {region.begin.line, region.begin.column};
}

std::string_view nodeKindText(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a floating-point number";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
        case toml::node_type::none:
            break;
    }
    return "a value";
}

// The value as the user wrote it; scalars are formatted like every other message value.
std::string nodeText(const toml::node& node) {
    if (const auto* s = node.as_string()) return formatParameterValue(s->get());
    if (const auto* i = node.as_integer()) return formatParameterValue(i->get());
    if (const auto* f = node.as_floating_point()) return formatParameterValue(f->get());
    if (const auto* b = node.as_boolean()) return formatParameterValue(b->get());
    std::ostringstream out;
    node.visit([&out](const auto& n) { out << n; });
    return out.str();
}

// The node as a value of the descriptor's type; an integer is also a number.
std::optional<ParameterValue> nodeValue(const toml::node& node, ParameterType type) {
    switch (type) {
        case ParameterType::Number:
            if (const auto* f = node.as_floating_point()) return ParameterValue(f->get());
            if (const auto* i = node.as_integer()) return ParameterValue(i->get());
            break;
        case ParameterType::Integer:
            if (const auto* i = node.as_integer()) return ParameterValue(i->get());
            break;
        case ParameterType::Bool:
            if (const auto* b = node.as_boolean()) return ParameterValue(b->get());
            break;
        case ParameterType::String:
        case ParameterType::Enum:
            if (const auto* s = node.as_string()) return ParameterValue(s->get());
            break;
    }
    return std::nullopt;
}

// Reads one parsed file into a MachineConfig, collecting every problem.
class MachineReader {
public:
    explicit MachineReader(std::string_view file) : m_file(file) {}

    void read(const toml::table& root) {
        bool baseOk = readBase(root);
        for (auto&& [key, node] : root) {
            if (key.str() == "base") continue;
            if (key.str() == "axes") {
                readAxes(key, node);
            } else {
                readEntry(key, node, "");
            }
        }
        sortAxes(m_config);
        // Checks across keys only make sense on top of a known base.
        if (baseOk) {
            DiagnosticList more = validateMachine(m_config, m_file, m_positions);
            m_diagnostics.insert(m_diagnostics.end(), more.begin(), more.end());
        }
    }

    const MachineConfig& config() const { return m_config; }
    DiagnosticList& diagnostics() { return m_diagnostics; }

    template <typename... Args>
    void report(TextPosition at, const char* messageTemplate, Args&&... args) {
        m_diagnostics.push_back(Diagnostic::make(Severity::Error, "config", m_file, at.line,
                                                 at.column, messageTemplate,
                                                 std::string(std::forward<Args>(args))...));
    }

private:
    bool readBase(const toml::table& root) {
        const toml::node* node = root.get("base");
        if (!node) return true;
        TextPosition at = positionOf(node->source());
        const auto* name = node->as_string();
        if (!name || builtinMachineToml(name->get()).empty()) {
            std::string names;
            for (std::string_view n : builtinMachineNames()) {
                names += names.empty() ? "" : ", ";
                names += n;
            }
            report(at, KERF_TR_NOOP("base = {1} is not a built-in machine ({2})"), nodeText(*node),
                   names);
            return false;
        }
        Expected<MachineConfig> base = loadMachine(name->get());
        if (!base) {
            m_diagnostics.push_back(base.error());
            return false;
        }
        m_config = std::move(base).value();
        m_positions["base"] = at;
        return true;
    }

    // A key of the machine scope: a parameter, or a table such as [spindle] holding some.
    void readEntry(const toml::key& key, const toml::node& node, const std::string& prefix) {
        std::string fullKey = prefix + std::string(key.str());
        const ParameterDescriptor* d = findParameter(fullKey);
        if (d && d->scope == ParameterScope::Machine) {
            readValue(*d, fullKey, node, AxisType::Linear);
        } else if (fullKey == kToolErrorKey) {
            readToolErrors(node);
        } else if (node.is_array() && isVectorSection(fullKey)) {
            readVector(fullKey, *node.as_array());
        } else if (isSection(fullKey)) {
            const toml::table* table = node.as_table();
            if (!table) {
                report(positionOf(node.source()), KERF_TR_NOOP("{1} must be a table"), fullKey);
                return;
            }
            for (auto&& [childKey, child] : *table)
                readEntry(childKey, child, fullKey + ".");
        } else {
            std::vector<std::string_view> candidates{"base", "axes"};
            for (const auto& p : machineParameters())
                candidates.push_back(p.key);
            reportUnknownKey(key, fullKey, std::string(detail::closestKey(fullKey, candidates)));
        }
    }

    static constexpr std::string_view kToolErrorKey = "simulation.tool_error";

    // [[simulation.tool_error]]: an array of tables, each with tool, length and radius.
    void readToolErrors(const toml::node& node) {
        const toml::array* array = node.as_array();
        if (array == nullptr || !array->is_array_of_tables()) {
            report(positionOf(node.source()),
                   KERF_TR_NOOP("{1} must be tables [[{1}]] with tool, length and radius"),
                   std::string(kToolErrorKey));
            return;
        }
        for (const toml::node& entry : *array) {
            ToolErrorConfig error;
            bool ok = true;
            for (auto&& [key, value] : *entry.as_table()) {
                const std::string fullKey =
                    std::string(kToolErrorKey) + "." + std::string(key.str());
                const TextPosition at = positionOf(value.source());
                const auto* integer = value.as_integer();
                const std::optional<double> number =
                    value.is_number() ? std::optional(value.as_floating_point()
                                                          ? value.as_floating_point()->get()
                                                          : static_cast<double>(integer->get()))
                                      : std::nullopt;
                if (key.str() == "centre_offset") {
                    ok = readCentreOffset(fullKey, value, error) && ok;
                } else if (key.str() == "tool" && integer && integer->get() >= 0 &&
                           integer->get() <= 32767) {
                    error.tool = static_cast<int>(integer->get());
                } else if ((key.str() == "length" || key.str() == "radius") && number &&
                           std::abs(*number) <= 10.0) {
                    (key.str() == "length" ? error.lengthMm : error.radiusMm) = *number;
                } else if (key.str() == "tool" || key.str() == "length" || key.str() == "radius") {
                    report(at,
                           KERF_TR_NOOP("{1} = {2} is out of range: a tool number 0 ... 32767, "
                                        "lengths within +-10 mm"),
                           fullKey, nodeText(value));
                    ok = false;
                } else {
                    reportUnknownKey(key, fullKey, "");
                    ok = false;
                }
            }
            if (!entry.as_table()->contains("tool")) {
                report(positionOf(entry.source()), KERF_TR_NOOP("{1} needs a tool number"),
                       std::string(kToolErrorKey));
                ok = false;
            } else if (ok && m_config.toolError(error.tool) != nullptr) {
                report(positionOf(entry.source()), KERF_TR_NOOP("{1}: tool {2} is given twice"),
                       std::string(kToolErrorKey), std::to_string(error.tool));
                ok = false;
            }
            if (ok) m_config.toolErrors.push_back(error);
        }
    }

    // centre_offset = [x, y]: a probe stylus's ball centre off the spindle axis, within +-10 mm.
    bool readCentreOffset(const std::string& fullKey, const toml::node& value,
                          ToolErrorConfig& error) {
        const toml::array* array = value.as_array();
        bool ok = array != nullptr && array->size() == 2;
        for (size_t i = 0; ok && i < 2; ++i) {
            const toml::node& component = *array->get(i);
            const std::optional<double> number =
                component.as_floating_point() ? std::optional(component.as_floating_point()->get())
                : component.as_integer()
                    ? std::optional(static_cast<double>(component.as_integer()->get()))
                    : std::nullopt;
            ok = number && std::abs(*number) <= 10.0;
            if (ok) error.centreOffsetMm[i] = *number;
        }
        if (!ok) {
            report(positionOf(value.source()),
                   KERF_TR_NOOP("{1} must be an array of two numbers [x, y] within +-10 mm, not "
                                "{2}"),
                   fullKey, nodeText(value));
        }
        return ok;
    }

    // A table of x, y and z (simulation.setup.shift) may be written as an array [x, y, z].
    void readVector(const std::string& fullKey, const toml::array& array) {
        if (array.size() != 3) {
            report(positionOf(array.source()),
                   KERF_TR_NOOP("{1} must be an array of three numbers [x, y, z], not {2}"),
                   fullKey, std::to_string(array.size()));
            return;
        }
        for (size_t i = 0; i < 3; ++i) {
            const std::string component = fullKey + "." + "xyz"[i];
            readValue(*findParameter(component), component, *array.get(i), AxisType::Linear);
        }
    }

    static bool isVectorSection(const std::string& key) {
        return findParameter(key + ".x") && findParameter(key + ".y") && findParameter(key + ".z");
    }

    void readAxes(const toml::key& key, const toml::node& node) {
        const toml::table* axes = node.as_table();
        if (!axes) {
            report(positionOf(key.source()),
                   KERF_TR_NOOP("axes must be a table of axes such as [axes.X]"));
            return;
        }
        for (auto&& [letterKey, axisNode] : *axes) {
            std::string tableKey = "axes." + std::string(letterKey.str());
            std::string_view letter = letterKey.str();
            if (letter.size() != 1 || !isAxisLetter(letter[0])) {
                report(positionOf(letterKey.source()),
                       KERF_TR_NOOP("{1}: {2} is not an axis letter; use one of {3}"), tableKey,
                       std::string(letter), std::string("X, Y, Z, A, B, C, U, V, W"));
                continue;
            }
            const toml::table* table = axisNode.as_table();
            if (!table) {
                report(positionOf(axisNode.source()), KERF_TR_NOOP("{1} must be a table"),
                       tableKey);
                continue;
            }
            readAxis(letter[0], letterKey, *table);
        }
    }

    void readAxis(char letter, const toml::key& tableKey, const toml::table& table) {
        if (!m_config.axis(letter)) m_config.axes.push_back(defaultAxis(letter));
        m_positions[std::string("axes.") + letter] = positionOf(tableKey.source());
        // The type goes first because it picks the units that range messages name.
        if (const toml::node* type = table.get("type")) readAxisEntry(letter, "type", *type);
        for (auto&& [key, node] : table) {
            if (key.str() == "type") continue;
            if (!findParameter(axisParameterKey(letter, key.str()))) {
                std::vector<std::string_view> candidates;
                for (const auto& p : axisParameters())
                    candidates.push_back(p.key);
                std::string_view close = detail::closestKey(key.str(), candidates);
                reportUnknownKey(key, axisParameterKey(letter, key.str()),
                                 close.empty() ? "" : axisParameterKey(letter, close));
                continue;
            }
            readAxisEntry(letter, key.str(), node);
        }
    }

    void readAxisEntry(char letter, std::string_view name, const toml::node& node) {
        std::string fullKey = axisParameterKey(letter, name);
        const ParameterDescriptor* d = findParameter(fullKey);
        if (d) readValue(*d, fullKey, node, m_config.axis(letter)->type);
    }

    void readValue(const ParameterDescriptor& d, const std::string& fullKey, const toml::node& node,
                   AxisType axisType) {
        TextPosition at = positionOf(node.source());
        std::optional<ParameterValue> value = nodeValue(node, d.type);
        if (!value) {
            std::string expected = expectedValueText(d);
            std::string_view unit = parameterUnit(d, axisType);
            if (!unit.empty()) expected += " (" + std::string(unit) + ")";
            if (node.is_table()) {
                report(at, KERF_TR_NOOP("{1} is a table; expected {2}"), fullKey, expected);
            } else {
                report(at, KERF_TR_NOOP("{1} = {2} is {3}; expected {4}"), fullKey, nodeText(node),
                       std::string(nodeKindText(node)), expected);
            }
            return;
        }
        if (MaybeError error = setParameter(m_config, fullKey, *value)) {
            error->file = m_file;
            error->line = at.line;
            error->column = at.column;
            m_diagnostics.push_back(std::move(*error));
            return;
        }
        m_positions[fullKey] = at;
    }

    void reportUnknownKey(const toml::key& key, const std::string& fullKey,
                          const std::string& suggestion) {
        TextPosition at = positionOf(key.source());
        if (suggestion.empty()) {
            report(at, KERF_TR_NOOP("unknown key {1}"), fullKey);
        } else {
            report(at, KERF_TR_NOOP("unknown key {1}; did you mean {2}?"), fullKey, suggestion);
        }
    }

    // True when some machine parameter lives inside the table `key` ("spindle").
    static bool isSection(std::string_view key) {
        return std::any_of(machineParameters().begin(), machineParameters().end(),
                           [key](const ParameterDescriptor& d) {
                               return d.key.size() > key.size() &&
                                      d.key.substr(0, key.size()) == key &&
                                      d.key[key.size()] == '.';
                           });
    }

    std::string m_file;
    MachineConfig m_config;
    KeyPositions m_positions;
    DiagnosticList m_diagnostics;
};

// File order; diagnostics without a line go last.
void sortByPosition(DiagnosticList& list) {
    auto rank = [](const Diagnostic& d) {
        return std::pair(d.line == 0 ? std::numeric_limits<uint32_t>::max() : d.line, d.column);
    };
    std::stable_sort(list.begin(), list.end(), [&rank](const Diagnostic& a, const Diagnostic& b) {
        return rank(a) < rank(b);
    });
}

Expected<MachineConfig> finish(std::optional<MachineConfig> config, DiagnosticList diagnostics,
                               DiagnosticList* problems) {
    sortByPosition(diagnostics);
    if (problems) *problems = diagnostics;
    if (hasErrors(diagnostics) || !config) {
        auto firstError =
            std::find_if(diagnostics.begin(), diagnostics.end(),
                         [](const Diagnostic& d) { return d.severity == Severity::Error; });
        return *firstError;
    }
    return std::move(*config);
}

}  // namespace

Expected<MachineConfig> parseMachine(std::string_view tomlText, std::string_view fileName,
                                     DiagnosticList* problems) {
    MachineReader reader(fileName);
    try {
        toml::table root = toml::parse(tomlText, fileName);
        reader.read(root);
    } catch (const toml::parse_error& e) {
        reader.report(positionOf(e.source()), KERF_TR_NOOP("TOML syntax error: {1}"),
                      std::string(e.description()));
        return finish(std::nullopt, std::move(reader.diagnostics()), problems);
    } catch (const std::exception& e) {
        // toml++ reports syntax errors by exception; nothing else may leave the module either.
        reader.report({}, KERF_TR_NOOP("cannot read the machine configuration: {1}"),
                      std::string(e.what()));
        return finish(std::nullopt, std::move(reader.diagnostics()), problems);
    }
    return finish(reader.config(), std::move(reader.diagnostics()), problems);
}

Expected<MachineConfig> loadMachine(std::string_view nameOrPath, DiagnosticList* problems) {
    std::string_view builtin = builtinMachineToml(nameOrPath);
    if (!builtin.empty()) {
        return parseMachine(builtin, "builtin:" + std::string(nameOrPath), problems);
    }
    Expected<std::string> text = readWholeFile(std::filesystem::path(std::string(nameOrPath)));
    if (!text) {
        if (problems) *problems = {text.error()};
        return text.error();
    }
    return parseMachine(*text, nameOrPath, problems);
}

}  // namespace kerf::machine
