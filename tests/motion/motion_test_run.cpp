#include "tests/motion/motion_test_run.h"

#include <cstring>
#include <memory>

#include "core/machine/machine_loader.h"

namespace kerf::motion::test {

machine::MachineConfig millConfig() {
    return *machine::loadMachine("mill");
}

machine::MachineConfig figuresMill() {
    machine::MachineConfig config = millConfig();
    for (auto& axis : config.axes)
        axis.maxAccelerationPerS2 = 1000.0;
    return config;
}

TestRun runCommands(
    const machine::MachineConfig& config, const std::vector<canon::Command>& commands,
    const Pose& start, SimulationOptions options,
    std::function<void(SimulatedMachine&, const Sample&, const MotionStatus&)> during) {
    // The hooks outlive this function (the machine is returned and may run on): they watch only
    // while the program runs here.
    struct Hooks {
        SampleChecker* checker = nullptr;
        SimulatedMachine* machine = nullptr;
        uint64_t hash = 1469598103934665603ull;
        std::function<void(const Sample&, const MotionStatus&)> previous;
        std::function<void(SimulatedMachine&, const Sample&, const MotionStatus&)> during;
    };
    auto hooks = std::make_shared<Hooks>();
    hooks->previous = options.onSample;
    hooks->during = std::move(during);
    options.startPosition = start.values;
    options.onSample = [hooks](const Sample& sample, const MotionStatus& status) {
        if (!hooks->machine) return;
        hooks->checker->addSample(sample);
        for (double value : sample.joints) {
            uint64_t bits = 0;
            std::memcpy(&bits, &value, sizeof bits);
            hooks->hash = (hooks->hash ^ bits) * 1099511628211ull;
        }
        if (hooks->previous) hooks->previous(sample, status);
        if (hooks->during) hooks->during(*hooks->machine, sample, status);
    };
    TestRun run;
    run.sim = std::make_unique<SimulatedMachine>(config, options);
    run.checker = std::make_unique<SampleChecker>(run.sim->model(), start);
    hooks->checker = run.checker.get();
    hooks->machine = run.sim.get();
    for (const canon::Command& command : commands) {
        run.checker->addCommand(command);
        run.sim->consume(command);
    }
    run.world = run.sim->drain();
    run.report = run.sim->report();
    run.sampleHash = hooks->hash;
    hooks->machine = nullptr;
    return run;
}

}  // namespace kerf::motion::test
