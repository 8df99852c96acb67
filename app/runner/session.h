#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/interp/interpreter.h"
#include "core/machine/machine_config.h"
#include "core/task/program_loader.h"

namespace kerf::app {

// Everything one headless run needs: the machine and the program loaded by task::loadProgram
// (its sources, tool table and interpreter). Problems of the machine file and the options are in
// `diagnostics`; the program's own in program.diagnostics().
struct Session {
    machine::MachineConfig machine;
    task::LoadedProgram program;
    DiagnosticList diagnostics;
    DiagnosticList allDiagnostics() const;
    // The files the run reads: the program, the tables, the programs loaded so far.
    std::vector<std::filesystem::path> inputs() const;
    bool ready() const { return program.ready; }  // loaded without errors: it can run
    const program::SourceRegistry& sources() const { return *program.sources; }
    // Machine coordinates of the stream's origin, motion's work offset: the workpiece origin
    // (machine file presets, --work-offset) or, for FAGOR, the zero offset active at the start.
    Pose workOffset{};
    std::vector<std::filesystem::path> setupFiles;  // the program and the tables, by fixed name
    std::filesystem::path ncRoot;                   // where the program's tables are read
};

// With `backgroundCheck` the program's check runs alongside execution (see
// KlartextInterpreter::CheckMode); the caller must then honour Interpreter::checkFailed().
// With `userScreen` a FAGOR program runs as that screen's customisation program. Without
// `writeFiles` (kerf check's dry run) the files the program writes are admitted, not written.
std::unique_ptr<Session> openSession(const RunOptions& options, bool backgroundCheck = false,
                                     fagor::UserScreen* userScreen = nullptr,
                                     bool writeFiles = true);

}  // namespace kerf::app
