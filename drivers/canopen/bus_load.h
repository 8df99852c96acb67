#pragma once

#include <chrono>
#include <cstdint>
#include <span>

// Bus load of a cyclic CANopen configuration (classical CAN, 11-bit identifiers): per cycle one
// SYNC plus the PDOs, each between 47 + 8n bits (no stuff bits) and its worst case with stuff
// bits (drivers/can/bit_timing.h); plus the heartbeats of every node and the master, averaged.
// SDO and EMCY traffic is not cyclic and must fit into what is left, hence the 80 % limit.
namespace kerf::drivers::canopen {

inline constexpr double kMaxBusLoad = 0.80;

struct BusLoad {
    uint32_t cycleBitsMin = 0;   // SYNC + PDOs of one cycle without stuff bits
    uint32_t cycleBitsMax = 0;   // ... with the most stuff bits
    uint32_t cycleBitTimes = 0;  // bit times in one cycle at the bit rate
    double heartbeatLoad = 0.0;  // share of the bus the heartbeats take
    double minimum = 0.0;        // share of the bus, best case
    double worstCase = 0.0;      // share of the bus, worst case: the figure that is checked
    bool acceptable() const noexcept { return worstCase <= kMaxBusLoad; }
};

// `pdoBytes` lists the payload size of every PDO sent per cycle (RPDOs and TPDOs of all nodes);
// `heartbeatProducers` counts the nodes (and master) sending a heartbeat every heartbeatPeriod.
BusLoad estimateBusLoad(uint32_t bitrate, std::chrono::nanoseconds cycle,
                        std::span<const uint8_t> pdoBytes, int heartbeatProducers,
                        std::chrono::milliseconds heartbeatPeriod) noexcept;

}  // namespace kerf::drivers::canopen
