#pragma once

#include <filesystem>
#include <string>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"
#include "core/program/dialect.h"

namespace kerf::ui {

// The static part of `kerf check` for a program text of `dialect`: loaded by task::loadProgram
// with the NC root's tables, not run (task::checkByRunning runs it). Kept in a file without Qt
// headers: Qt's `emit` macro collides with the interpreters' emit() members.
DiagnosticList checkProgramText(std::string text, const std::string& path, program::Dialect dialect,
                                const machine::MachineConfig& machine,
                                const std::filesystem::path& ncRoot);

}  // namespace kerf::ui
