#include "drivers/canopen/nmt.h"

#include "drivers/canopen/cob_id.h"

namespace kerf::drivers::canopen {

const char* nmtStateName(NmtState state) noexcept {
    switch (state) {
        case NmtState::BootUp:
            return "boot-up";
        case NmtState::Stopped:
            return "stopped";
        case NmtState::Operational:
            return "operational";
        case NmtState::PreOperational:
            return "pre-operational";
    }
    return "?";
}

can::CanFrame nmtFrame(NmtCommand command, uint8_t node) noexcept {
    return can::makeFrame(kNmtId, {static_cast<uint8_t>(command), node});
}

can::CanFrame heartbeatFrame(uint8_t node, NmtState state) noexcept {
    return can::makeFrame(kHeartbeatBase + node, {static_cast<uint8_t>(state)});
}

bool parseHeartbeat(const can::CanFrame& frame, uint8_t& node, NmtState& state) noexcept {
    if (frame.extended || frame.remote || functionCode(frame.id) != kHeartbeatBase ||
        frame.length != 1 || nodeOf(frame.id) == 0) {
        return false;
    }
    switch (frame.data[0] & 0x7F) {
        case 0x00:
            state = NmtState::BootUp;
            break;
        case 0x04:
            state = NmtState::Stopped;
            break;
        case 0x05:
            state = NmtState::Operational;
            break;
        case 0x7F:
            state = NmtState::PreOperational;
            break;
        default:
            return false;
    }
    node = nodeOf(frame.id);
    return true;
}

}  // namespace kerf::drivers::canopen
