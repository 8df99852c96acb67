#include "ui/session/program_interpreter.h"

#include <algorithm>
#include <cctype>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/tnciso/tnciso.h"
#include "core/program/nc_root.h"

namespace kerf::ui {

namespace fs = std::filesystem;

namespace {

bool isLathe(const machine::MachineConfig& machine) {
    return machine.kind == machine::MachineKind::Lathe;
}

}  // namespace

std::string programName(const fs::path& path) {
    return path.empty() ? std::string("MDI") : path.string();
}

LoadedProgram loadProgram(const machine::MachineConfig& machine, const ProgramSource& source) {
    LoadedProgram loaded;
    loaded.sources = std::make_unique<program::SourceRegistry>();
    const std::string name = programName(source.path);
    const program::Dialect dialect =
        source.dialect ? *source.dialect
                       : program::dialectForFile(source.path.string(), isLathe(machine));
    if (dialect == program::Dialect::Fagor) {
        fagor::FagorSettings settings;
        settings.machine = &machine;
        settings.ncRoot = source.ncRoot;
        settings.toolOffsetFile = source.ncRoot / "fagor_tool_offsets.tab";
        settings.zeroOffsetFile = source.ncRoot / "fagor_zero_offsets.tab";
        settings.toolFile = source.ncRoot / "fagor_tools.tab";
        settings.presetInMachine = source.presetInMachine;
        auto fagor = std::make_unique<fagor::FagorInterpreter>(*loaded.sources, settings);
        const bool ok = fagor->loadText(source.text, name);
        loaded.diagnostics = fagor->diagnostics();
        loaded.streamOrigin = fagor->streamOrigin();
        if (ok) loaded.interpreter = std::move(fagor);
        return loaded;
    }
    std::error_code error;
    const fs::path toolFile = source.ncRoot / "TOOL.T";
    if (fs::exists(fs::symlink_status(toolFile, error))) {
        // Through the NC root's file-access layer: no link out, no FIFO (docs/files.md).
        auto bytes = program::NcRoot(source.ncRoot).read(toolFile);
        auto tools = bytes ? tables::ToolTable::parse(*bytes, toolFile.string()) : bytes.error();
        if (!tools) {
            loaded.diagnostics.push_back(tools.error());
            return loaded;
        }
        loaded.tools = std::make_unique<tables::ToolTable>(std::move(*tools));
    }
    // Conversational and DIN/ISO programs run on the same TNC engine (docs/tnciso.md).
    klartext::KlartextSettings settings;
    tnciso::enableIso(settings, dialect == program::Dialect::TncIso);
    settings.machine = &machine;
    settings.tools = loaded.tools.get();
    settings.ncRoot = source.ncRoot;
    settings.startPosition = source.startPosition;
    settings.presetInMachine = source.presetInMachine;
    auto klartext = std::make_unique<klartext::KlartextInterpreter>(*loaded.sources, settings);
    const bool ok = klartext->loadText(source.text, name);
    loaded.diagnostics = klartext->diagnostics();
    if (ok) loaded.interpreter = std::move(klartext);
    return loaded;
}

std::string mdiProgram(const machine::MachineConfig& machine, const std::string& block) {
    if (isLathe(machine)) return block + "\n";
    // The operator may type the block with or without its number.
    size_t start = block.find_first_not_of(" \t");
    if (start == std::string::npos) start = block.size();
    size_t body = start;
    while (body < block.size() && std::isdigit(static_cast<unsigned char>(block[body])))
        ++body;
    if (body == start || (body < block.size() && block[body] != ' ')) body = start;
    body = std::min(block.size(), block.find_first_not_of(" \t", body));
    return "0 BEGIN PGM MDI MM\n1 " + block.substr(body) + "\n2 END PGM MDI MM\n";
}

}  // namespace kerf::ui
