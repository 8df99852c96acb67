#pragma once

#include <filesystem>
#include <string>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"

namespace kerf::ui {

// Checks a TNC program text (conversational, or DIN/ISO when `iso`) as `kerf check` would. Kept
// in a file without Qt headers: Qt's `emit` macro collides with the interpreter's emit() member.
DiagnosticList checkKlartextText(std::string text, const std::string& path,
                                 const machine::MachineConfig& machine,
                                 const std::filesystem::path& ncRoot, bool iso = false);

}  // namespace kerf::ui
