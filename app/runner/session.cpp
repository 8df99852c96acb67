#include "app/runner/session.h"

#include <cstdlib>

#include "app/runner/headless_operator.h"
#include "app/runner/workpiece_origin.h"
#include "core/machine/machine_loader.h"
#include "core/program/nc_root.h"
#include "core/tables/preset_table.h"

namespace kerf::app {

namespace fs = std::filesystem;

namespace {

Diagnostic setupError(const std::string& file, const char* text, std::string arg = {}) {
    return Diagnostic::make(Severity::Error, "setup", file, 0, 0, text, std::move(arg));
}

// --preset n: PRESET.PR of the NC root, which must have row n.
std::optional<tables::PresetTable> presetTable(const fs::path& ncRoot, int row,
                                               DiagnosticList& diagnostics) {
    const fs::path file = ncRoot / "PRESET.PR";
    auto bytes = program::NcRoot(ncRoot).read(file);
    auto table = bytes ? tables::PresetTable::parse(*bytes, file.string()) : bytes.error();
    if (!table) {
        diagnostics.push_back(table.error());
        return std::nullopt;
    }
    if (table->byNumber(row) == nullptr) {
        diagnostics.push_back(setupError(
            file.string(), KERF_TR_NOOP("--preset {1}: the preset table has no such row"),
            std::to_string(row)));
        return std::nullopt;
    }
    return std::move(*table);
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
    appendDiagnostics(all, program.diagnostics());
    return all;
}

std::vector<fs::path> Session::inputs() const {
    std::vector<fs::path> all = setupFiles;
    if (program.sources) {
        for (uint32_t id = 0; id < program.sources->size(); ++id)
            all.emplace_back(program.sources->path(id));
    }
    return all;
}

std::unique_ptr<Session> openSession(const RunOptions& options, bool backgroundCheck,
                                     fagor::UserScreen* userScreen, bool writeFiles) {
    auto session = std::make_unique<Session>();
    DiagnosticList machineProblems;
    auto machine = machine::loadMachine(options.machine, &machineProblems);
    if (!machine) {
        session->diagnostics =
            machineProblems.empty() ? DiagnosticList{machine.error()} : machineProblems;
        return session;
    }
    session->machine = *machine;
    task::ProgramRequest request;
    if (options.dialect) {
        request.dialect = program::dialectFromName(*options.dialect);
        if (!request.dialect) {
            session->diagnostics.push_back(
                setupError("", KERF_TR_NOOP("unknown dialect '{1}' (klartext, tnciso, fagor)"),
                           *options.dialect));
            return session;
        }
    }
    request.path = fs::absolute(options.program);
    request.ncRoot = options.ncRoot ? fs::absolute(*options.ncRoot) : request.path.parent_path();
    request.toolTable = options.toolTable;
    for (const auto* output : {&options.traceFile, &options.samples, &options.reportFile,
                               &options.png, &options.canTrace}) {
        if (*output && **output != "-") request.runOutputs.push_back(fs::absolute(**output));
    }
    request.blockSkip = options.blockSkip;
    // Motion in simulated time latches the probe; the drive chain's bus does not model one.
    request.touchesFromMachine = (options.motion || options.samples) && !options.drives;
    std::optional<tables::PresetTable> presets;
    if (options.preset) {
        presets = presetTable(request.ncRoot, *options.preset, session->diagnostics);
        if (!presets) return session;
        request.basicRotationDeg = presets->basicRotationDeg(*options.preset);
    }
    const Pose origin = workpieceOrigin(session->machine, options.workOffset,
                                        presets ? presets->byNumber(*options.preset) : nullptr);
    session->workOffset = origin;
    request.presetInMachine = origin;
    request.backgroundCheck = backgroundCheck;
    request.writeFiles = writeFiles;
    request.userScreen = userScreen;
    // "IBn=value" items of --operator-input: the operator's inputs any FAGOR program may read.
    for (const std::string& option : options.operatorInput) {
        size_t start = 0;
        for (;;) {
            const size_t comma = option.find(',', start);
            const std::string item = option.substr(start, comma - start);
            if (auto assignment = inputAssignment(item)) {
                request.operatorInputs.push_back(*assignment);
            } else if (!userScreen) {
                session->diagnostics.push_back(setupError(
                    "",
                    KERF_TR_NOOP("--operator-input '{1}': IBn=value expected (n 0-25); keys "
                                 "and bare numbers need --user-screen"),
                    item));
                return session;
            }
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    const fs::path stateDir = options.stateDir ? *options.stateDir : defaultStateDir();
    if (!stateDir.empty()) {
        std::error_code ignored;
        fs::create_directories(stateDir, ignored);
        request.remanentFile = stateDir / "qr_parameters.txt";
    }
    session->ncRoot = request.ncRoot;
    session->setupFiles.push_back(request.path);
    for (const char* table : {"TOOL.T", "PRESET.PR", "fagor_tool_offsets.tab",
                              "fagor_zero_offsets.tab", "fagor_tools.tab"}) {
        session->setupFiles.push_back(request.ncRoot / table);
    }
    if (options.toolTable) session->setupFiles.push_back(*options.toolTable);
    session->program = task::loadProgram(session->machine, request);
    if (session->program.streamOrigin) session->workOffset = *session->program.streamOrigin;
    return session;
}

}  // namespace kerf::app
