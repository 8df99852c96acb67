#include "drivers/canopen/bus_load.h"

#include "drivers/can/bit_timing.h"

namespace kerf::drivers::canopen {

BusLoad estimateBusLoad(uint32_t bitrate, std::chrono::nanoseconds cycle,
                        std::span<const uint8_t> pdoBytes, int heartbeatProducers,
                        std::chrono::milliseconds heartbeatPeriod) noexcept {
    BusLoad load;
    load.cycleBitsMin = can::unstuffedBitCount(0);
    load.cycleBitsMax = can::worstCaseBitCount(0);
    for (uint8_t bytes : pdoBytes) {
        load.cycleBitsMin += can::unstuffedBitCount(bytes);
        load.cycleBitsMax += can::worstCaseBitCount(bytes);
    }
    double cycleS = std::chrono::duration<double>(cycle).count();
    double bitsPerS = static_cast<double>(bitrate);
    load.cycleBitTimes = static_cast<uint32_t>(cycleS * bitsPerS + 0.5);
    if (heartbeatPeriod.count() > 0 && bitsPerS > 0.0) {
        double periodS = std::chrono::duration<double>(heartbeatPeriod).count();
        load.heartbeatLoad = static_cast<double>(heartbeatProducers) * can::worstCaseBitCount(1) /
                             periodS / bitsPerS;
    }
    if (load.cycleBitTimes == 0) {
        load.minimum = load.worstCase = 1e9;
        return load;
    }
    auto cycleBits = static_cast<double>(load.cycleBitTimes);
    load.minimum = load.cycleBitsMin / cycleBits;
    load.worstCase = load.cycleBitsMax / cycleBits + load.heartbeatLoad;
    return load;
}

}  // namespace kerf::drivers::canopen
