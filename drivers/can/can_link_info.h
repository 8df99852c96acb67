#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>

#include "drivers/can/can_channel.h"

// Bit rate and controller state of a CAN network interface, read over rtnetlink the way
// `ip -details link show can0` does. Normal threads only (one netlink round trip).
namespace kerf::drivers::can {

struct CanLinkInfo {
    uint32_t bitrate = 0;  // bit/s; 0 when the driver reports no bit timing
    ControllerState state = ControllerState::Stopped;
};

// Errors: no_such_device, CanErrc::NotCanInterface (e.g. "lo", or vcan, which has no bit timing),
// CanErrc::MalformedReply, or the errno of the netlink socket.
std::error_code readCanLinkInfo(std::string_view interface, CanLinkInfo& out);

// Parses one RTM_NEWLINK message (netlink header included).
std::error_code parseCanLinkMessage(std::span<const uint8_t> message, CanLinkInfo& out) noexcept;

}  // namespace kerf::drivers::can
