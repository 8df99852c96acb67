#include "core/machine/machine_writer.h"

#include <algorithm>

#include "core/base/atomic_file.h"
#include "core/machine/machine_schema.h"

namespace kerf::machine {

namespace {

// Like formatParameterValue, but numbers keep a decimal point so the file shows they are floats.
std::string tomlValue(const ParameterValue& value) {
    std::string text = formatParameterValue(value);
    if (std::holds_alternative<double>(value) && text.find_first_of(".na") == std::string::npos) {
        text += ".0";
    }
    return text;
}

void writeLine(std::string& out, std::string_view name, const ParameterValue& value,
               std::string_view unit) {
    out += name;
    out += " = ";
    out += tomlValue(value);
    if (!unit.empty()) {
        out += "  # ";
        out += unit;
    }
    out += '\n';
}

// Writes the machine parameters whose key lies in `section` ("" for the top level).
void writeSection(std::string& out, const MachineConfig& config, std::string_view section) {
    for (const ParameterDescriptor& d : machineParameters()) {
        size_t dot = d.key.rfind('.');
        std::string_view keySection = dot == std::string_view::npos ? "" : d.key.substr(0, dot);
        if (keySection != section) continue;
        std::string_view name = dot == std::string_view::npos ? d.key : d.key.substr(dot + 1);
        Expected<ParameterValue> value = getParameter(config, d.key);
        if (value) writeLine(out, name, *value, d.unit);
    }
}

}  // namespace

std::string toToml(const MachineConfig& config) {
    std::string out =
        "# Kerf machine configuration; keys, units and ranges: docs/machine-config.md\n";
    writeSection(out, config, "");
    std::vector<std::string_view> sections;
    for (const ParameterDescriptor& d : machineParameters()) {
        size_t dot = d.key.rfind('.');
        if (dot == std::string_view::npos) continue;
        std::string_view section = d.key.substr(0, dot);
        if (std::find(sections.begin(), sections.end(), section) != sections.end()) continue;
        sections.push_back(section);
        out += "\n[";
        out += section;
        out += "]\n";
        writeSection(out, config, section);
    }
    for (const ToolErrorConfig& error : config.toolErrors) {
        out += "\n[[simulation.tool_error]]\n";
        writeLine(out, "tool", int64_t{error.tool}, "");
        writeLine(out, "length", error.lengthMm, "mm");
        writeLine(out, "radius", error.radiusMm, "mm");
        if (error.centreOffsetMm != std::array<double, 2>{0.0, 0.0}) {
            out += "centre_offset = [" + tomlValue(error.centreOffsetMm[0]) + ", " +
                   tomlValue(error.centreOffsetMm[1]) + "]  # mm\n";
        }
    }
    for (const AxisConfig& axis : config.axes) {
        out += "\n[axes.";
        out += axis.letter;
        out += "]\n";
        for (const ParameterDescriptor& d : axisParameters()) {
            // Fails only for a letter that is no axis letter; the loader reports that table.
            Expected<ParameterValue> value =
                getParameter(config, axisParameterKey(axis.letter, d.key));
            if (value) writeLine(out, d.key, *value, parameterUnit(d, axis.type));
        }
    }
    return out;
}

MaybeError saveMachine(const MachineConfig& config, const std::filesystem::path& path) {
    return writeFileAtomically(path, toToml(config));
}

}  // namespace kerf::machine
