#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/interp/interpreter.h"
#include "core/machine/machine_config.h"
#include "core/program/dialect.h"
#include "core/program/source_registry.h"
#include "core/tables/tool_table.h"

// The one place where a program enters Kerf: a file or an editor's text plus a machine becomes a
// ready interpreter with its dialect, tables, NC root and diagnostics. `kerf run`, `kerf check`,
// the HMI's program run, MDI, test run and the editor's live check all load through it, so a
// program checks, test-runs and runs the same everywhere.
namespace kerf::fagor {
class UserScreen;
}

namespace kerf::workpiece {
class RemovedMaterial;
}

namespace kerf::task {

struct ProgramRequest {
    std::filesystem::path path;       // names the program, decides the dialect; empty: MDI
    std::optional<std::string> text;  // the editor's text; without it the file is read
    // Without it the file and the machine decide (.H Klartext, .I TNC ISO, anything else the
    // machine's: FAGOR on a lathe).
    std::optional<program::Dialect> dialect;
    std::filesystem::path ncRoot;  // its TOOL.T and FAGOR tables; the programs it may call
    std::optional<std::filesystem::path> toolTable;  // any file instead of the NC root's TOOL.T
    std::vector<std::filesystem::path> runOutputs;   // files the run writes: never read as input
    std::filesystem::path remanentFile;              // where QR parameters are kept; empty: not
    bool blockSkip = false;
    // False for a dry run (the editor's check): files the program writes are checked, not written.
    bool writeFiles = true;
    // Where the tool tip stands, workpiece coordinates; unset: at the origin the program's
    // coordinates start from (kerf run).
    std::optional<Pose> startPosition;
    Pose presetInMachine{};  // the workpiece origin, machine coordinates (M91, FAGOR G53/G74)
    double basicRotationDeg = 0.0;  // the active preset's basic rotation (TNC programs)
    // Check alongside execution (KlartextInterpreter::CheckMode::Background); the caller must
    // then honour Interpreter::checkFailed().
    bool backgroundCheck = false;
    // FAGOR: run as the user customisation program of this screen (the user channel, spec part 2
    // §6.8); it must outlive the interpreter.
    fagor::UserScreen* userScreen = nullptr;
    // FAGOR: the values of the IBn variables the operator gave for this run (n, value).
    std::vector<std::pair<int, double>> operatorInputs;
    // An MDI block: starts with this spindle speed S, and (TNC) its end leaves the spindle and
    // the coolant running (a FAGOR block without M30 does anyway).
    bool mdi = false;
    double spindleRpm = 0.0;
    // TNC: how the spindle turns when the block starts (a TOOL CALL S then changes its speed).
    canon::SpindleDirection spindle = canon::SpindleDirection::Stopped;
    // TNC: the probing cycles' touches come from the machine's latch (the program runs on motion
    // that latches: `kerf run --motion`, the panel's machine); false: the interpreter decides
    // them on its simulated part.
    bool touchesFromMachine = false;
};

struct LoadedProgram {
    std::unique_ptr<program::SourceRegistry> sources;
    std::unique_ptr<tables::ToolTable> tools;
    // Present whenever the tables could be read, also when the program has errors (its
    // diagnostics, later the run's, are the interpreter's).
    std::unique_ptr<interp::Interpreter> interpreter;
    program::Dialect dialect = program::Dialect::Klartext;
    // FAGOR: the origin the program's coordinates start from (zero offset table or the preset),
    // machine coordinates; motion must use it.
    std::optional<Pose> streamOrigin;
    // TNC: what the program cuts out of its blank as it runs (the part its probing cycles touch,
    // core/workpiece); nothing for FAGOR.
    std::shared_ptr<const workpiece::RemovedMaterial> removedMaterial;
    DiagnosticList setupDiagnostics;  // tables that could not be read
    bool ready = false;               // loaded and checked without errors: it may run

    // The setup's and the interpreter's diagnostics so far.
    DiagnosticList diagnostics() const;
};

// The name the program's blocks carry in the SourceRegistry ("MDI" without a file).
std::string programName(const std::filesystem::path& path);

LoadedProgram loadProgram(const machine::MachineConfig& machine, const ProgramRequest& request);

// One MDI block as a program of the machine's dialect (Klartext: between BEGIN PGM and END PGM).
std::string mdiProgram(const machine::MachineConfig& machine, const std::string& block);

}  // namespace kerf::task
