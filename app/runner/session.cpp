#include "app/runner/session.h"

#include <cstdlib>

#include "app/runner/workpiece_origin.h"
#include "core/base/atomic_file.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/tnciso/tnciso.h"
#include "core/machine/machine_loader.h"
#include "core/program/nc_root.h"

namespace kerf::app {

namespace fs = std::filesystem;

namespace {

Diagnostic setupError(const std::string& file, const char* text, std::string arg = {}) {
    return Diagnostic::make(Severity::Error, "setup", file, 0, 0, text, std::move(arg));
}

fs::path defaultStateDir() {
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) return fs::path(xdg) / "kerf";
    if (const char* home = std::getenv("HOME"); home && *home) {
        return fs::path(home) / ".local" / "share" / "kerf";
    }
    return {};
}

}  // namespace

DiagnosticList Session::allDiagnostics() const {
    DiagnosticList all = diagnostics;
    if (interpreter) {
        appendDiagnostics(all, interpreter->diagnostics());
    }
    return all;
}

std::vector<fs::path> Session::inputs() const {
    std::vector<fs::path> all = setupFiles;
    for (uint32_t id = 0; id < sources.size(); ++id)
        all.emplace_back(sources.path(id));
    return all;
}

std::unique_ptr<Session> openSession(const RunOptions& options, bool backgroundCheck) {
    auto session = std::make_unique<Session>();
    DiagnosticList machineProblems;
    auto machine = machine::loadMachine(options.machine, &machineProblems);
    if (!machine) {
        session->diagnostics =
            machineProblems.empty() ? DiagnosticList{machine.error()} : machineProblems;
        return session;
    }
    session->machine = *machine;
    const Pose origin = workpieceOrigin(session->machine, options.workOffset);
    session->workOffset = origin;
    const bool lathe = session->machine.kind == machine::MachineKind::Lathe;
    if (options.dialect) {
        auto dialect = program::dialectFromName(*options.dialect);
        if (!dialect) {
            session->diagnostics.push_back(
                setupError("", KERF_TR_NOOP("unknown dialect '{1}' (klartext, tnciso, fagor)"),
                           *options.dialect));
            return session;
        }
        session->dialect = *dialect;
    } else {
        session->dialect = program::dialectForFile(options.program.string(), lathe);
    }
    const fs::path programPath = fs::absolute(options.program);
    const fs::path ncRoot =
        options.ncRoot ? fs::absolute(*options.ncRoot) : programPath.parent_path();
    std::error_code ignored;
    const program::NcRoot root(ncRoot);
    session->setupFiles.push_back(programPath);
    for (const char* table : {"TOOL.T", "PRESET.PR", "fagor_tool_offsets.tab",
                              "fagor_zero_offsets.tab", "fagor_tools.tab"}) {
        session->setupFiles.push_back(ncRoot / table);
    }
    std::optional<fs::path> toolFile = options.toolTable;
    if (toolFile) session->setupFiles.push_back(*toolFile);
    if (!toolFile && fs::exists(fs::symlink_status(ncRoot / "TOOL.T", ignored))) {
        toolFile = ncRoot / "TOOL.T";
    }
    if (toolFile) {
        // --tool-table names any file; TOOL.T of the NC root has to be inside it.
        auto bytes = options.toolTable ? readWholeFile(*toolFile) : root.read(*toolFile);
        auto tools = bytes ? tables::ToolTable::parse(*bytes, toolFile->string()) : bytes.error();
        if (!tools) {
            session->diagnostics.push_back(tools.error());
            return session;
        }
        session->tools = std::move(*tools);
    }
    if (session->dialect == program::Dialect::Fagor) {
        // The FAGOR tables live in the NC root (docs/fagor.md, "Tables").
        fagor::FagorSettings settings;
        settings.machine = &session->machine;
        settings.ncRoot = ncRoot;
        settings.toolOffsetFile = ncRoot / "fagor_tool_offsets.tab";
        settings.zeroOffsetFile = ncRoot / "fagor_zero_offsets.tab";
        settings.toolFile = ncRoot / "fagor_tools.tab";
        settings.blockSkip = options.blockSkip ? 1 : 0;
        settings.presetInMachine = origin;
        auto interpreter =
            std::make_unique<fagor::FagorInterpreter>(session->sources, std::move(settings));
        session->workOffset = interpreter->streamOrigin();
        session->ready = interpreter->load(
            programPath, backgroundCheck ? fagor::FagorInterpreter::CheckMode::Background
                                         : fagor::FagorInterpreter::CheckMode::Inline);
        session->interpreter = std::move(interpreter);
        return session;
    }
    // Conversational and DIN/ISO programs run on the same TNC engine (docs/tnciso.md).
    klartext::KlartextSettings settings;
    tnciso::enableIso(settings, session->dialect == program::Dialect::TncIso);
    settings.machine = &session->machine;
    settings.tools = session->tools ? &*session->tools : nullptr;
    if (toolFile) settings.toolTableFile = *toolFile;
    settings.ncRoot = ncRoot;
    settings.blockSkip = options.blockSkip;
    settings.presetInMachine = origin;
    fs::path stateDir = options.stateDir ? *options.stateDir : defaultStateDir();
    if (!stateDir.empty()) {
        fs::create_directories(stateDir, ignored);
        settings.remanentFile = stateDir / "qr_parameters.txt";
    }
    auto interpreter =
        std::make_unique<klartext::KlartextInterpreter>(session->sources, std::move(settings));
    session->ready = interpreter->load(
        programPath, backgroundCheck ? klartext::KlartextInterpreter::CheckMode::Background
                                     : klartext::KlartextInterpreter::CheckMode::Inline);
    session->interpreter = std::move(interpreter);
    return session;
}

}  // namespace kerf::app
