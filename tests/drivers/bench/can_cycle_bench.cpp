// CPU time of the CAN part of one servo cycle (DriveBusAdapter::read + write: receiving frames,
// the master, CiA 402 decoding and supervision, RPDOs and SYNC) with 4 and 8 simulated drives,
// and the bus load of common configurations. The simulated bus and drives run between the
// measured calls and are not counted. Run: drivers_bench [--benchmark_repetitions=N].
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>

#include <benchmark/benchmark.h>

#include "core/machine/machine_loader.h"
#include "drivers/setup/can_sim_drive_set.h"
#include "motion/port/motion_status.h"

namespace kerf::drivers {
namespace {

using Clock = std::chrono::steady_clock;

// The mill (X Y Z + spindle, 2 ms SYNC) or the mill with A, B, C and U too (8 nodes, 4 ms).
machine::MachineConfig machineWith(int nodes) {
    machine::MachineConfig config = machine::loadMachine("mill").value();
    if (nodes == 8) {
        int node = 5;
        for (char letter : std::string("ABCU")) {
            machine::AxisConfig axis = machine::defaultAxis(letter);
            axis.driveNode = node++;
            axis.minLimit = -1000.0;
            axis.maxLimit = 1000.0;
            config.axes.push_back(axis);
        }
        machine::sortAxes(config);
        config.drives.cyclePeriodMs = 4.0;
    }
    return config;
}

void canCycle(benchmark::State& state) {
    auto nodes = static_cast<int>(state.range(0));
    auto set = CanSimDriveSet::create(machineWith(nodes), {}).value();
    if (set->boot()) {
        state.SkipWithError("boot failed");
        return;
    }
    motion::DriveBus& bus = set->bus();
    auto joints = static_cast<size_t>(bus.jointCount());
    std::array<motion::JointFeedback, motion::kMaxJoints> feedback{};
    std::array<motion::JointSetpoint, motion::kMaxJoints> setpoints{};
    bus.read({feedback.data(), joints});
    for (size_t j = 0; j < joints; ++j)
        setpoints[j].position = feedback[j].position;
    double periodS = std::chrono::duration<double>(set->config().servoPeriod).count();
    const canopen::Master& master = set->stack().master();
    double syncNs = 0.0;
    double otherNs = 0.0;
    double maxNs = 0.0;
    int64_t syncCycles = 0;
    int64_t otherCycles = 0;
    for (auto _ : state) {
        for (size_t j = 0; j + 1 < joints; ++j)
            setpoints[j].position += 0.005;     // 5 mm/s
        setpoints[joints - 1].position += 6.0;  // 1000 rpm
        uint64_t syncs = master.syncCount();
        Clock::time_point begin = Clock::now();
        bus.read({feedback.data(), joints});
        bus.write({setpoints.data(), joints});
        double ns = std::chrono::duration<double, std::nano>(Clock::now() - begin).count();
        state.SetIterationTime(ns * 1e-9);
        maxNs = std::max(maxNs, ns);
        if (master.syncCount() != syncs) {
            syncNs += ns;
            ++syncCycles;
        } else {
            otherNs += ns;
            ++otherCycles;
        }
        set->advance(periodS);
    }
    if (set->stopped()) state.SkipWithError("the drive set stopped");
    state.counters["sync_cycle_ns"] = syncCycles ? syncNs / static_cast<double>(syncCycles) : 0.0;
    state.counters["other_cycle_ns"] =
        otherCycles ? otherNs / static_cast<double>(otherCycles) : 0.0;
    state.counters["max_ns"] = maxNs;
    state.counters["bus_load_pct"] = set->measuredBusLoad() * 100.0;
}
BENCHMARK(canCycle)->Arg(4)->Arg(8)->UseManualTime()->Unit(benchmark::kMicrosecond);

void printBusLoadTable() {
    using namespace std::chrono_literals;
    std::printf(
        "CAN bus load, one 6-byte RPDO and TPDO per node and cycle, SYNC, heartbeats 10 ms\n");
    std::printf("%-6s %-10s %-8s %-26s %s\n", "nodes", "bit rate", "cycle", "bits/cycle (min-max)",
                "load (min - worst)  verdict");
    struct Row {
        int nodes;
        uint32_t bitrate;
        std::chrono::nanoseconds cycle;
    };
    const Row rows[] = {{2, 1000000, 1ms}, {3, 1000000, 1ms}, {4, 1000000, 1ms}, {4, 1000000, 2ms},
                        {6, 1000000, 2ms}, {8, 1000000, 2ms}, {8, 1000000, 4ms}, {4, 500000, 2ms},
                        {4, 500000, 4ms},  {4, 250000, 8ms}};
    for (const Row& r : rows) {
        canopen::BusLoad load = canBusLoad(r.nodes, r.bitrate, r.cycle, 10ms);
        std::printf("%-6d %-10u %-8g %4u-%-4u of %-13u %5.1f - %5.1f %%     %s\n", r.nodes,
                    r.bitrate, std::chrono::duration<double, std::milli>(r.cycle).count(),
                    load.cycleBitsMin, load.cycleBitsMax, load.cycleBitTimes, load.minimum * 100.0,
                    load.worstCase * 100.0, load.acceptable() ? "accepted" : "refused (> 80 %)");
    }
}

}  // namespace
}  // namespace kerf::drivers

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    kerf::drivers::printBusLoadTable();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
