#pragma once

#include <cstdint>

#include <linux/can.h>

#include "drivers/can/can_channel.h"
#include "drivers/can/socketcan_channel.h"

// Conversions between CanFrame and the kernel's struct can_frame, filters and error frames: the
// socket-free part of the SocketCAN back-end, tested on machines without PF_CAN.
namespace kerf::drivers::can::detail {

struct can_frame toKernelFrame(const CanFrame& frame) noexcept;
// False for error frames, which are not data.
bool fromKernelFrame(const struct can_frame& kernel, CanFrame& frame) noexcept;
struct can_filter toKernelFilter(const CanFilter& filter) noexcept;

// What an error frame (CAN_ERR_FLAG set) says about the controller.
struct ErrorFrameInfo {
    bool stateChanged = false;
    ControllerState state = ControllerState::ErrorActive;
    bool overflow = false;  // the controller lost received or queued frames
};
ErrorFrameInfo decodeErrorFrame(const struct can_frame& kernel, ControllerState current) noexcept;

}  // namespace kerf::drivers::can::detail
