#pragma once

#include <cstdint>

#include "drivers/can/can_frame.h"

// NMT commands (COB-ID 0x000, {command, node-ID}; node 0 addresses every node) and the NMT
// states a node reports in its heartbeat (COB-ID 0x700 + node, one byte). Pure, any thread.
namespace kerf::drivers::canopen {

enum class NmtCommand : uint8_t {
    Start = 0x01,
    Stop = 0x02,
    EnterPreOperational = 0x80,
    ResetNode = 0x81,
    ResetCommunication = 0x82,
};

enum class NmtState : uint8_t {
    BootUp = 0x00,  // the boot-up message: the node entered Pre-operational
    Stopped = 0x04,
    Operational = 0x05,
    PreOperational = 0x7F,
};

const char* nmtStateName(NmtState state) noexcept;

can::CanFrame nmtFrame(NmtCommand command, uint8_t node) noexcept;
can::CanFrame heartbeatFrame(uint8_t node, NmtState state) noexcept;
// False unless `frame` is a one-byte heartbeat of node 1..127 with a known state.
bool parseHeartbeat(const can::CanFrame& frame, uint8_t& node, NmtState& state) noexcept;

}  // namespace kerf::drivers::canopen
