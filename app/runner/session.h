#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/interp/interpreter.h"
#include "core/machine/machine_config.h"
#include "core/program/dialect.h"
#include "core/program/source_registry.h"
#include "core/tables/tool_table.h"

namespace kerf::app {

// Everything one headless run needs: the machine, the tool table, the loaded program and its
// interpreter. Problems found while setting up (machine, tables, dialect) are in `diagnostics`;
// the program's own are in interpreter->diagnostics().
struct Session {
    machine::MachineConfig machine;
    std::optional<tables::ToolTable> tools;
    program::SourceRegistry sources;
    program::Dialect dialect = program::Dialect::Klartext;
    std::unique_ptr<interp::Interpreter> interpreter;
    DiagnosticList diagnostics;
    DiagnosticList allDiagnostics() const;
    // The files the run reads: the program, the tables, the programs loaded so far.
    std::vector<std::filesystem::path> inputs() const;
    bool ready = false;  // the program loaded without errors and can run
    // Machine coordinates of the stream's origin, motion's work offset: the workpiece origin
    // (machine file presets, --work-offset) or, for FAGOR, the zero offset active at the start.
    Pose workOffset{};
    std::vector<std::filesystem::path> setupFiles;  // the program and the tables, by fixed name
};

// With `backgroundCheck` the program's check runs alongside execution (see
// KlartextInterpreter::CheckMode); the caller must then honour Interpreter::checkFailed().
std::unique_ptr<Session> openSession(const RunOptions& options, bool backgroundCheck = false);

}  // namespace kerf::app
