#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "core/canon/commands.h"
#include "core/machine/machine_config.h"
#include "motion/sim/simulated_machine.h"
#include "tests/motion/sample_checker.h"

// Runs canonical commands through a SimulatedMachine with a SampleChecker watching the samples.
namespace kerf::motion::test {

struct TestRun {
    std::unique_ptr<SimulatedMachine> sim;
    std::unique_ptr<SampleChecker> checker;
    MotionReport report;
    interp::WorldSnapshot world;
    uint64_t sampleHash = 0;  // of every sample's joint setpoints (determinism)
};

machine::MachineConfig millConfig();
// The mill with the accelerations of shared/anchors/FIGURES.md (1000 mm/s^2 on every axis).
machine::MachineConfig figuresMill();

// `during` is called after every sample (operator commands at chosen times).
TestRun runCommands(
    const machine::MachineConfig& config, const std::vector<canon::Command>& commands,
    const Pose& start, SimulationOptions options = {},
    std::function<void(SimulatedMachine&, const Sample&, const MotionStatus&)> during = {});

}  // namespace kerf::motion::test
