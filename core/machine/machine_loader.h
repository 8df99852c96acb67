#pragma once

#include <string_view>

#include "core/base/expected.h"
#include "core/machine/machine_config.h"

namespace kerf::machine {

// Loads a built-in machine ("mill", "lathe") or a TOML file (any other string is a path).
//
// A file may give only some keys: the others keep their schema defaults, or the values of the
// built-in machine named by `base = "mill"`. Loading does not stop at the first problem: every
// problem found (syntax error, unknown key, wrong type, value out of range, inconsistent values)
// becomes one diagnostic "file:line:column: error: ...", in file order, followed by those that
// have no position. On failure the result holds the first of them; pass `problems` to get all.
// Nothing is thrown.
Expected<MachineConfig> loadMachine(std::string_view nameOrPath,
                                    DiagnosticList* problems = nullptr);

// Same for TOML text already in memory; `fileName` names it in diagnostics.
Expected<MachineConfig> parseMachine(std::string_view tomlText, std::string_view fileName,
                                     DiagnosticList* problems = nullptr);

}  // namespace kerf::machine
