#pragma once

#include <string_view>
#include <vector>

namespace kerf::machine {

// Names of the machines available without a file: "mill", "mill4", "mill5", "mill5h", "mill5hh",
// "lathe".
const std::vector<std::string_view>& builtinMachineNames();

// The TOML text of a built-in machine (the files in core/machine/presets/, embedded at build
// time), or an empty view for other names. Load it with loadMachine(name).
std::string_view builtinMachineToml(std::string_view name);

}  // namespace kerf::machine
