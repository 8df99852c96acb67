#pragma once

#include <string>

namespace kerf::ui {

// Starts the operator panel on the given machine (built-in name or TOML file) and runs the Qt
// event loop; returns the process exit code.
int runHmi(int argc, char** argv, const std::string& machine);

}  // namespace kerf::ui
