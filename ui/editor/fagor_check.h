#pragma once

#include <filesystem>
#include <string>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"

namespace kerf::ui {

// Checks a FAGOR 8035 T program text as `kerf check` would, with the FAGOR tables of the NC root
// (docs/fagor.md, "Tables"). The program is only checked, never run, so no table is written.
// Kept in a file without Qt headers: Qt's `emit` macro collides with the interpreter's emit().
DiagnosticList checkFagorText(std::string text, const std::string& path,
                              const machine::MachineConfig& machine,
                              const std::filesystem::path& ncRoot);

}  // namespace kerf::ui
