#include "core/task/program_loader.h"

#include <algorithm>
#include <cctype>

#include "core/base/atomic_file.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/tnciso/tnciso.h"
#include "core/program/nc_root.h"

namespace kerf::task {

namespace fs = std::filesystem;

namespace {

bool isLathe(const machine::MachineConfig& machine) {
    return machine.kind == machine::MachineKind::Lathe;
}

// The tool table: a file named by the user (any path), else TOOL.T of the NC root read through
// its file-access layer (no link out, no FIFO: docs/files.md). False when it cannot be read.
bool readTools(const ProgramRequest& request, LoadedProgram& loaded) {
    std::error_code ignored;
    const fs::path rootTable = request.ncRoot / "TOOL.T";
    const bool inRoot =
        !request.ncRoot.empty() && fs::exists(fs::symlink_status(rootTable, ignored));
    if (!request.toolTable && !inRoot) return true;
    const fs::path file = request.toolTable ? *request.toolTable : rootTable;
    auto bytes =
        request.toolTable ? readWholeFile(file) : program::NcRoot(request.ncRoot).read(file);
    auto tools = bytes ? tables::ToolTable::parse(*bytes, file.string()) : bytes.error();
    if (!tools) {
        loaded.setupDiagnostics.push_back(tools.error());
        return false;
    }
    loaded.tools = std::make_unique<tables::ToolTable>(std::move(*tools));
    return true;
}

template <typename Interpreter, typename Mode>
bool load(Interpreter& interpreter, const ProgramRequest& request, Mode mode) {
    if (request.text) return interpreter.loadText(*request.text, programName(request.path));
    return interpreter.load(request.path, mode);
}

void loadFagor(const machine::MachineConfig& machine, const ProgramRequest& request,
               LoadedProgram& loaded) {
    fagor::FagorSettings settings;
    settings.machine = &machine;
    settings.ncRoot = request.ncRoot;
    settings.runOutputs = request.runOutputs;
    if (!request.ncRoot.empty()) {
        // The FAGOR tables live in the NC root (docs/fagor.md, "Tables").
        settings.toolOffsetFile = request.ncRoot / "fagor_tool_offsets.tab";
        settings.zeroOffsetFile = request.ncRoot / "fagor_zero_offsets.tab";
        settings.toolFile = request.ncRoot / "fagor_tools.tab";
    }
    settings.blockSkip = request.blockSkip ? 1 : 0;
    settings.presetInMachine = request.presetInMachine;
    if (request.startPosition) {
        Pose start = *request.startPosition;
        for (size_t i = 0; i < start.values.size(); ++i)
            start.values[i] += request.presetInMachine.values[i];
        settings.startInMachine = start;
    }
    settings.userScreen = request.userScreen;
    settings.writeFiles = request.writeFiles;
    settings.startSpindleRpm = request.spindleRpm;
    for (const auto& [n, value] : request.operatorInputs) {
        if (n >= 0 && n < static_cast<int>(settings.inputValues.size()))
            settings.inputValues[static_cast<size_t>(n)] = value;
    }
    auto interpreter = std::make_unique<fagor::FagorInterpreter>(*loaded.sources, settings);
    loaded.streamOrigin = interpreter->streamOrigin();
    loaded.ready = load(*interpreter, request,
                        request.backgroundCheck ? fagor::FagorInterpreter::CheckMode::Background
                                                : fagor::FagorInterpreter::CheckMode::Inline);
    loaded.interpreter = std::move(interpreter);
}

void loadTnc(const machine::MachineConfig& machine, const ProgramRequest& request,
             LoadedProgram& loaded) {
    // Conversational and DIN/ISO programs run on the same TNC engine (docs/tnciso.md).
    klartext::KlartextSettings settings;
    tnciso::enableIso(settings, loaded.dialect == program::Dialect::TncIso);
    settings.machine = &machine;
    settings.tools = loaded.tools.get();
    // The TT cycles write measured tools back; empty: TOOL.T of the NC root.
    if (request.toolTable) settings.toolTableFile = *request.toolTable;
    settings.ncRoot = request.ncRoot;
    settings.runOutputs = request.runOutputs;
    settings.blockSkip = request.blockSkip;
    settings.startPosition = request.startPosition.value_or(Pose{});
    settings.startPositionKnown = request.startPosition.has_value();
    settings.presetInMachine = request.presetInMachine;
    settings.basicRotationDeg = request.basicRotationDeg;
    settings.remanentFile = request.remanentFile;
    settings.writeFiles = request.writeFiles;
    settings.slReturnToStart = machine.slReturnToStart;
    settings.mdi = request.mdi;
    settings.startSpindleRpm = request.spindleRpm;
    settings.startSpindle = request.spindle;
    settings.touchesFromMachine = request.touchesFromMachine;
    auto interpreter = std::make_unique<klartext::KlartextInterpreter>(*loaded.sources, settings);
    loaded.removedMaterial = interpreter->removedMaterial();
    loaded.ready =
        load(*interpreter, request,
             request.backgroundCheck ? klartext::KlartextInterpreter::CheckMode::Background
                                     : klartext::KlartextInterpreter::CheckMode::Inline);
    loaded.interpreter = std::move(interpreter);
}

}  // namespace

DiagnosticList LoadedProgram::diagnostics() const {
    DiagnosticList all = setupDiagnostics;
    if (interpreter) appendDiagnostics(all, interpreter->diagnostics());
    return all;
}

std::string programName(const fs::path& path) {
    return path.empty() ? std::string("MDI") : path.string();
}

LoadedProgram loadProgram(const machine::MachineConfig& machine, const ProgramRequest& request) {
    LoadedProgram loaded;
    loaded.sources = std::make_unique<program::SourceRegistry>();
    loaded.dialect = request.dialect
                         ? *request.dialect
                         : program::dialectForFile(request.path.string(), isLathe(machine));
    if (loaded.dialect == program::Dialect::Fagor) {
        loadFagor(machine, request, loaded);
        return loaded;
    }
    if (!readTools(request, loaded)) return loaded;
    loadTnc(machine, request, loaded);
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

}  // namespace kerf::task
