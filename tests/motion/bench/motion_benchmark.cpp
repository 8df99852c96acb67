// Planning throughput and servo cycle CPU time (Google Benchmark).
//   motion_benchmark --benchmark_filter=Plan     segments planned per second (gen_nc rasters)
//   motion_benchmark --benchmark_filter=Servo    servo cycle CPU time, mean / p99 / worst
// The servo cycle is timed with the thread's CPU clock: time the thread was not running (another
// process on a loaded machine) does not count; what a real-time thread would need does.
#include <algorithm>
#include <ctime>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "motion/planner/planner.h"
#include "motion/rt/servo_cycle.h"
#include "motion/sim/sim_drive_set.h"
#include "tests/motion/motion_test_run.h"
#include "tests/motion/raster_program.h"

namespace kerf::motion {
namespace {

struct Collect final : canon::Sink {
    std::vector<canon::Command> commands;
    void consume(const canon::Command& c) override { commands.push_back(c); }
};

std::vector<canon::Command> rasterCommands(int blocks, double seg, double feed) {
    Collect collect;
    test::RasterOptions options;
    options.blocks = blocks;
    options.segMm = seg;
    options.feedMmPerMin = feed;
    test::emitRaster(options, collect);
    return collect.commands;
}

// Arguments: segment length in µm, axis jerk in mm/s^3 (the filter, and so the window of
// curvature steps, is longer at a lower jerk).
void PlanRaster(benchmark::State& state) {
    const double seg = static_cast<double>(state.range(0)) / 1000.0;
    auto commands = rasterCommands(20000, seg, 6000.0);
    machine::MachineConfig config = test::figuresMill();
    for (auto& axis : config.axes)
        axis.maxJerkPerS3 = static_cast<double>(state.range(1));
    MachineModel model = makeMachineModel(config, {});
    size_t elements = 0;
    for (auto _ : state) {
        Planner planner(model);
        planner.setPosition(test::rasterStart().values);
        for (const canon::Command& c : commands) {
            planner.add(c);
            while (auto item = planner.next())
                ++elements;
        }
        planner.flush();
        while (auto item = planner.next())
            ++elements;
    }
    state.counters["segments/s"] = benchmark::Counter(
        static_cast<double>(commands.size()) * static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate);
    state.counters["elements/segment"] =
        static_cast<double>(elements) /
        (static_cast<double>(commands.size()) * static_cast<double>(state.iterations()));
}
BENCHMARK(PlanRaster)
    ->ArgsProduct({{200, 50, 20, 5}, {50000, 1000000}})
    ->Unit(benchmark::kMillisecond);

machine::MachineConfig withAxes(int axes) {
    machine::MachineConfig config = test::millConfig();
    if (axes == 5) {
        for (char letter : {'A', 'C'}) {
            machine::AxisConfig axis = machine::defaultAxis(letter);
            axis.minLimit = -36000.0;
            axis.maxLimit = 36000.0;
            config.axes.push_back(axis);
        }
        machine::sortAxes(config);
    }
    return config;
}

// Five-axis work: the raster with A and C turning along each move.
std::vector<canon::Command> withRotation(std::vector<canon::Command> commands) {
    double angle = 0.0;
    for (canon::Command& c : commands) {
        angle += 0.05;
        if (auto* l = std::get_if<canon::LinearMove>(&c.body)) {
            l->target[Axis::A] = angle;
            l->target[Axis::C] = 2.0 * angle;
        } else if (auto* a = std::get_if<canon::ArcMove>(&c.body)) {
            a->target[Axis::A] = angle;
            a->target[Axis::C] = 2.0 * angle;
        }
    }
    return commands;
}

double threadCpuMicroseconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e6 + static_cast<double>(now.tv_nsec) * 1e-3;
}

// Arguments: axes, segment length in µm (the 5 µm raster passes up to ~20 element ends per
// cycle; enough blocks that the program outlasts the 60,000 cycles).
void ServoCycleCpu(benchmark::State& state) {
    const int axes = static_cast<int>(state.range(0));
    const double seg = static_cast<double>(state.range(1)) / 1000.0;
    machine::MachineConfig config = withAxes(axes);
    MachineModel model = makeMachineModel(config, {});
    auto commands = rasterCommands(static_cast<int>(60000 * 0.05 / seg), seg, 6000.0);
    if (axes == 5) commands = withRotation(std::move(commands));
    Planner planner(model);
    planner.setPosition(test::rasterStart().values);
    std::vector<MotionItem> planned;
    for (const canon::Command& c : commands) {
        planner.add(c);
        while (auto item = planner.next())
            planned.push_back(*item);
    }
    planner.flush();
    while (auto item = planner.next())
        planned.push_back(*item);

    SimDriveSet drives(model, {});
    std::array<double, kMaxJoints> start{};
    for (int j = 0; j < model.jointCount; ++j) {
        int axis = model.jointAxis[static_cast<size_t>(j)];
        if (axis >= 0)
            start[static_cast<size_t>(j)] = test::rasterStart().values[static_cast<size_t>(axis)];
    }
    drives.setTruePositions(start);
    auto items = std::make_unique<ItemRing>();
    CommandRing operatorCommands;
    EventRing events;
    ServoCycle servo(model, drives, *items, operatorCommands, events);
    servo.start();
    size_t next = 0;
    std::vector<double> times;
    times.reserve(1 << 20);
    for (auto _ : state) {
        while (next < planned.size() && items->push(planned[next]))
            ++next;
        if (items->empty()) {
            state.SkipWithError("program ended before the benchmark");
            break;
        }
        const double begin = threadCpuMicroseconds();
        servo.cycle();
        const double end = threadCpuMicroseconds();
        drives.advance(model.periodS);
        while (!events.empty())
            events.pop();
        times.push_back(end - begin);
    }
    if (times.empty()) return;
    std::sort(times.begin(), times.end());
    double sum = 0.0;
    for (double t : times)
        sum += t;
    state.counters["mean_us"] = sum / static_cast<double>(times.size());
    state.counters["p99_us"] = times[times.size() * 99 / 100];
    state.counters["worst_us"] = times.back();
    state.counters["cycles"] = static_cast<double>(times.size());
}
BENCHMARK(ServoCycleCpu)
    ->Args({3, 50})
    ->Args({5, 50})
    ->Args({3, 5})
    ->Iterations(60000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace kerf::motion

BENCHMARK_MAIN();
