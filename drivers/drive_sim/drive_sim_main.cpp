// kerf-drive-sim: serves the simulated CiA 402 drives of a machine on the UDP CAN bus, so that a
// master in another process (kerf, a test) drives them as if they were on a real bus. The drives
// share an in-process bus whose frames are bridged to and from the UDP channel; time is the
// wall clock. Runs until SIGINT/SIGTERM or --seconds.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/machine/machine_loader.h"
#include "drivers/can/udp_channel.h"
#include "drivers/can/virtual_bus.h"
#include "drivers/setup/can_bus_config.h"
#include "drivers/setup/fault_injection.h"
#include "drivers/setup/sim_drive_factory.h"

namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) {
    g_stop = true;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace kerf;
    using std::chrono::nanoseconds;
    CLI::App app{
        "Simulated CiA 402 drives on the UDP CAN bus (cannelloni v2 datagrams on 127.0.0.1)"};
    std::string machineName = "mill";
    uint16_t port = 0;
    uint16_t peer = 0;
    double seconds = 0.0;
    std::vector<std::string> faultSpecs;
    app.add_option("--machine", machineName, "Built-in machine or TOML file with the drive nodes");
    app.add_option("--port", port, "UDP port of the drives (0: any free port)");
    app.add_option("--peer", peer, "UDP port of the master")->required();
    app.add_option("--seconds", seconds, "Stop after this many seconds (0: on SIGINT/SIGTERM)");
    app.add_option("--inject-fault", faultSpecs, "NODE:KIND@SECONDS, seconds since start");
    CLI11_PARSE(app, argc, argv);

    Expected<machine::MachineConfig> machine = machine::loadMachine(machineName);
    if (!machine) {
        std::fprintf(stderr, "kerf-drive-sim: %s\n", machine.error().format().c_str());
        return 2;
    }
    Expected<drivers::CanBusConfig> config = drivers::makeCanBusConfig(*machine);
    if (!config) {
        std::fprintf(stderr, "kerf-drive-sim: %s\n", config.error().message().c_str());
        return 2;
    }
    std::vector<drivers::FaultInjection> faults;
    for (const std::string& spec : faultSpecs) {
        Expected<drivers::FaultInjection> f = drivers::parseFaultInjection(spec);
        if (!f) {
            std::fprintf(stderr, "kerf-drive-sim: %s\n", f.error().message().c_str());
            return 2;
        }
        faults.push_back(*f);
    }
    std::sort(faults.begin(), faults.end(),
              [](const auto& a, const auto& b) { return a.timeS < b.timeS; });

    drivers::can::UdpChannel udp;
    uint16_t peers[] = {peer};
    if (std::error_code error = udp.open(port, peers)) {
        std::fprintf(stderr, "kerf-drive-sim: cannot open UDP port %u: %s\n", port,
                     error.message().c_str());
        return 2;
    }
    // The drives share an in-process bus; the bridge endpoint relays to and from UDP.
    drivers::can::VirtualBus bus(0);
    drivers::can::VirtualChannel& bridge = bus.attach("udp");
    std::vector<std::unique_ptr<drivers::sim::SimDrive>> drives;
    std::vector<drivers::CanJoint> joints;  // of each drive
    std::string nodes;
    for (const drivers::CanJoint& joint : config->joints) {
        if (joint.node == 0) continue;
        joints.push_back(joint);
        drivers::can::VirtualChannel& channel = bus.attach("node " + std::to_string(joint.node));
        drives.push_back(std::make_unique<drivers::sim::SimDrive>(
            drivers::makeSimDriveConfig(*config, joint), channel));
        nodes += (nodes.empty() ? "" : ",") + std::to_string(joint.node);
    }
    std::printf("kerf-drive-sim: nodes %s on udp port %u, master on port %u\n", nodes.c_str(),
                udp.localPort(), peer);
    std::fflush(stdout);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);

    auto start = std::chrono::steady_clock::now();
    auto elapsed = [&start]() {
        return std::chrono::duration_cast<nanoseconds>(std::chrono::steady_clock::now() - start);
    };
    for (auto& d : drives)
        d->powerOn(elapsed());
    size_t nextFault = 0;
    while (!g_stop && (seconds <= 0.0 || elapsed() < std::chrono::duration<double>(seconds))) {
        nanoseconds now = elapsed();
        drivers::can::CanFrame frame;
        while (udp.receive(frame))
            bridge.send(frame);
        bus.advanceTo(now);
        for (; nextFault < faults.size(); ++nextFault) {
            const drivers::FaultInjection& f = faults[nextFault];
            if (std::chrono::duration<double>(now).count() < f.timeS) break;
            for (size_t i = 0; i < drives.size(); ++i) {
                if (drives[i]->node() == f.node) {
                    drivers::injectDriveFault(*drives[i], *config, joints[i], f.kind, now);
                }
            }
        }
        for (auto& d : drives)
            d->poll(now);
        bus.advanceTo(now);
        while (bridge.receive(frame))
            udp.send(frame);
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    std::printf("kerf-drive-sim: stopped after %.3f s\n",
                std::chrono::duration<double>(elapsed()).count());
    return 0;
}
