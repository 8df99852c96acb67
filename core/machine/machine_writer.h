#pragma once

#include <filesystem>
#include <string>

#include "core/base/expected.h"
#include "core/machine/machine_config.h"

namespace kerf::machine {

// The whole configuration as TOML: every parameter of the schema, with its unit as a comment.
// parseMachine(toToml(c)) gives back c exactly.
std::string toToml(const MachineConfig& config);

// Writes toToml(config) so that a crash leaves the old file or the new one, never a mix.
MaybeError saveMachine(const MachineConfig& config, const std::filesystem::path& path);

}  // namespace kerf::machine
