#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/machine/machine_config.h"

// Machines and helpers of the drive-set tests.
namespace kerf::drivers::test {

// The built-in mill: X, Y, Z and the spindle on nodes 1-4, 2 ms SYNC cycle, 1 ms servo cycle.
machine::MachineConfig mill();
// The mill with only its X axis on the bus (node 1) and no spindle drive, SYNC = servo = 1 ms.
machine::MachineConfig oneAxis();

// "ID#DATA" of every line of a candump log, and the lines themselves.
std::vector<std::string> traceFrames(const std::filesystem::path& log);
std::vector<std::string> traceLines(const std::filesystem::path& log);

std::filesystem::path tempFile(const std::string& name);

}  // namespace kerf::drivers::test
