#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/base/expected.h"
#include "core/machine/machine_config.h"
#include "drivers/canopen/bus_load.h"
#include "drivers/cia402/drive_axis.h"

// The CANopen drive bus of a machine, taken from its configuration ([drives], axes.<L>.drive_node,
// spindle.drive_node ...) and checked: every enabled axis needs a drive, and the cyclic traffic
// must fit into 80 % of the bus. Joints are in motion's order: the enabled axes in the order
// X Y Z A B C U V W, then the spindle. Configuration thread.
namespace kerf::drivers {

struct CanJoint {
    char axis = 'X';   // axis letter; 'S' for the spindle
    uint8_t node = 0;  // CANopen node-ID; 0: no drive (only the spindle may have none)
    cia402::Mode mode = cia402::Mode::CyclicPosition;
    bool rotary = false;
    double countsPerUnit = 10000.0;     // drive units per mm or degree
    double followingErrorWindow = 0.0;  // mm or deg; 0 for the spindle (velocity mode)
    double maxVelocity = 0.0;           // per s
    double maxAcceleration = 0.0;       // per s^2, also the quick-stop deceleration
};

struct CanBusConfig {
    std::string interface;
    uint32_t bitrate = 1000000;
    std::chrono::nanoseconds servoPeriod{std::chrono::milliseconds(1)};
    std::chrono::nanoseconds cyclePeriod{std::chrono::milliseconds(1)};
    uint8_t masterNode = 127;
    std::chrono::milliseconds heartbeatPeriod{10};
    std::chrono::milliseconds heartbeatTimeout{30};
    int pdoLossCycles = 3;
    std::chrono::milliseconds sdoTimeout{200};
    std::optional<uint32_t> vendorId;
    std::optional<uint32_t> productCode;
    std::vector<CanJoint> joints;
    canopen::BusLoad load;

    int nodeCount() const noexcept;
};

// Fails with a diagnostic naming the key (an axis without drive_node) or giving the bus load.
Expected<CanBusConfig> makeCanBusConfig(const machine::MachineConfig& config);

// The bus load of `nodes` CSP/CSV drives (one 6-byte RPDO and TPDO each per cycle) plus their
// and the master's heartbeats.
canopen::BusLoad canBusLoad(int nodes, uint32_t bitrate, std::chrono::nanoseconds cycle,
                            std::chrono::milliseconds heartbeatPeriod);

// "4 nodes, 1000 kbit/s, 2 ms cycle: 40-52 % (worst case 52.0 % with heartbeats)".
std::string describeBusLoad(int nodes, uint32_t bitrate, std::chrono::nanoseconds cycle,
                            const canopen::BusLoad& load);

}  // namespace kerf::drivers
