#include "tests/drivers/system/test_machines.h"

#include <fstream>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"

namespace kerf::drivers::test {

machine::MachineConfig mill() {
    return machine::loadMachine("mill").value();
}

machine::MachineConfig oneAxis() {
    machine::MachineConfig config = mill();
    config.axes.resize(1);
    config.spindle.driveNode = 0;
    config.drives.cyclePeriodMs = 1.0;
    return config;
}

std::vector<std::string> traceLines(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::vector<std::string> traceFrames(const std::filesystem::path& log) {
    std::vector<std::string> frames;
    for (const std::string& line : traceLines(log))
        frames.push_back(line.substr(line.rfind(' ') + 1));
    return frames;
}

std::filesystem::path tempFile(const std::string& name) {
    return std::filesystem::path(testing::TempDir()) / ("kerf_drivers_" + name);
}

}  // namespace kerf::drivers::test
