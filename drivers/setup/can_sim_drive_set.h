#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include "core/base/expected.h"
#include "core/machine/machine_config.h"
#include "drivers/can/candump_log.h"
#include "drivers/can/virtual_bus.h"
#include "drivers/setup/can_drive_stack.h"
#include "drivers/setup/fault_injection.h"
#include "drivers/sim/sim_drive.h"
#include "motion/port/drive_bus.h"

// A complete simulated CANopen drive set for headless runs and tests: a virtual CAN bus with the
// machine's bit rate, one simulated CiA 402 drive per configured node, and the master with its
// DriveBus adapter, all in simulated time. motion's servo cycle uses bus() like any DriveBus and
// calls advance() after each cycle, where the bus and the drives run one servo period event by
// event (each frame delivered when its transmission ends, each drive reacting at that time).
// Faults are injected by node, kind and time; every frame can be written as a candump log.
//
// Use (one thread):
//   auto set = CanSimDriveSet::create(config, options);   // refuses > 80 % bus load
//   set->setInitialPositions(joints);                      // where the joints stand
//   set->boot();                                           // boot, configure, enable
//   ... each servo cycle: servo.cycle() (read/write on set->bus()); set->advance(period) ...
//   set->diagnostics(); set->finish();
namespace kerf::drivers {

struct CanSimOptions {
    std::filesystem::path tracePath;  // candump log of every frame; empty: none
    // The trace stops growing here (about 1.5 h of the built-in mill's traffic); a warning
    // says so.
    uint64_t traceLimitBytes = uint64_t{1} << 30;
    std::vector<FaultInjection> faults;
    double bootTimeoutS = 10.0;
    // A run through the chain ends with an error after this much simulated time (from the end
    // of the boot): a program that does not end cannot hang it.
    double maxSimulatedS = 3600.0;
};

class CanSimDriveSet {
public:
    static Expected<std::unique_ptr<CanSimDriveSet>> create(const machine::MachineConfig& config,
                                                            CanSimOptions options);
    ~CanSimDriveSet();
    CanSimDriveSet(const CanSimDriveSet&) = delete;
    CanSimDriveSet& operator=(const CanSimDriveSet&) = delete;

    // Joint positions (motion's joint order and units) where the drives stand at power-on.
    void setInitialPositions(std::span<const double> joints);
    // Powers the drives on and runs simulated time, holding every joint where it stands, until
    // every drive is operational and follows its setpoint; fails with the reason (a boot failure
    // names node and object).
    MaybeError boot();

    motion::DriveBus& bus() noexcept { return m_stack->bus(); }
    // One servo period of bus and drives; call after each servo cycle.
    void advance(double periodS) noexcept;
    double timeS() const noexcept { return std::chrono::duration<double>(m_now).count(); }

    // A drive fault, lost heartbeat or PDO, ... stopped the set (see diagnostics()).
    bool stopped() const noexcept { return m_stack->adapter().stopped(); }
    DiagnosticList diagnostics() const;
    // Share of the bus the frames took since power-on.
    double measuredBusLoad() const noexcept;
    // Closes the trace; fails when it could not be written completely.
    MaybeError finish();

    const CanBusConfig& config() const noexcept { return m_config; }
    // Tests and benchmarks.
    CanDriveStack& stack() noexcept { return *m_stack; }
    can::VirtualBus& virtualBus() noexcept { return m_bus; }
    can::VirtualChannel& masterChannel() noexcept { return m_masterChannel; }
    size_t driveCount() const noexcept { return m_drives.size(); }
    sim::SimDrive& drive(size_t i) noexcept { return *m_drives[i].drive; }
    sim::SimDrive* driveForNode(uint8_t node) noexcept;

private:
    struct Drive {
        can::VirtualChannel* channel = nullptr;
        std::unique_ptr<sim::SimDrive> drive;
        int joint = -1;
    };

    CanSimDriveSet(CanBusConfig config, CanSimOptions options);
    void applyFault(const FaultInjection& fault) noexcept;
    Drive* driveOf(uint8_t node) noexcept;

    CanBusConfig m_config;
    CanSimOptions m_options;
    can::VirtualBus m_bus;
    can::VirtualChannel& m_masterChannel;
    std::vector<Drive> m_drives;
    std::unique_ptr<CanDriveStack> m_stack;
    can::CandumpWriter m_trace;
    std::vector<FaultInjection> m_timedFaults;  // by time
    size_t m_nextFault = 0;
    std::chrono::nanoseconds m_now{0};
    MaybeError m_traceError;
};

}  // namespace kerf::drivers
