#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "core/base/diagnostic.h"
#include "core/interp/interpreter.h"
#include "core/machine/machine_config.h"
#include "core/program/dialect.h"
#include "core/program/source_registry.h"
#include "core/tables/tool_table.h"

namespace kerf::ui {

// The interpreter for a program on the machine or in the test run, loaded from the editor's
// text and checked. It reads the NC root's tool table.
struct LoadedProgram {
    std::unique_ptr<program::SourceRegistry> sources;
    std::unique_ptr<tables::ToolTable> tools;
    std::unique_ptr<interp::Interpreter> interpreter;  // nullptr: diagnostics say why
    // FAGOR: the origin the program's coordinates start from (zero offset table or the preset),
    // machine coordinates; motion must use it.
    std::optional<Pose> streamOrigin;
    DiagnosticList diagnostics;
};

struct ProgramSource {
    std::string text;
    std::filesystem::path path;  // names the program in messages; decides the dialect
    std::filesystem::path ncRoot;
    Pose startPosition{};  // where the tool tip stands, workpiece coordinates
    // The editor's dialect; without it the file and the machine decide (.H Klartext, .I TNC ISO,
    // anything else the machine's: FAGOR on a lathe).
    std::optional<program::Dialect> dialect;
    Pose presetInMachine{};  // the workpiece origin, machine coordinates (M91, FAGOR G53/G74)
};

// The name the program's blocks carry in the interpreter's SourceRegistry ("MDI" without a file).
std::string programName(const std::filesystem::path& path);

LoadedProgram loadProgram(const machine::MachineConfig& machine, const ProgramSource& source);

// One MDI block as a program of its own dialect (Klartext: between BEGIN PGM and END PGM).
std::string mdiProgram(const machine::MachineConfig& machine, const std::string& block);

}  // namespace kerf::ui
