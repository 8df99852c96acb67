#include "ui/editor/fagor_check.h"

#include "core/interp/fagor/fagor_interpreter.h"
#include "core/program/source_registry.h"

namespace kerf::ui {

DiagnosticList checkFagorText(std::string text, const std::string& path,
                              const machine::MachineConfig& machine,
                              const std::filesystem::path& ncRoot) {
    program::SourceRegistry sources;
    fagor::FagorSettings settings;
    settings.machine = &machine;
    settings.ncRoot = ncRoot;
    if (!ncRoot.empty()) {
        settings.toolOffsetFile = ncRoot / "fagor_tool_offsets.tab";
        settings.zeroOffsetFile = ncRoot / "fagor_zero_offsets.tab";
        settings.toolFile = ncRoot / "fagor_tools.tab";
    }
    fagor::FagorInterpreter interpreter(sources, std::move(settings));
    interpreter.loadText(std::move(text), path);
    return interpreter.diagnostics();
}

}  // namespace kerf::ui
