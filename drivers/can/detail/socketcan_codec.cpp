#include "drivers/can/detail/socketcan_codec.h"

#include <cstring>

#include <linux/can/error.h>

namespace kerf::drivers::can::detail {

struct can_frame toKernelFrame(const CanFrame& frame) noexcept {
    struct can_frame kernel;
    std::memset(&kernel, 0, sizeof kernel);
    kernel.can_id =
        frame.extended ? (frame.id & CAN_EFF_MASK) | CAN_EFF_FLAG : frame.id & CAN_SFF_MASK;
    if (frame.remote) kernel.can_id |= CAN_RTR_FLAG;
    kernel.can_dlc = frame.length > kMaxDataLength ? kMaxDataLength : frame.length;
    if (!frame.remote) std::memcpy(kernel.data, frame.data.data(), kernel.can_dlc);
    return kernel;
}

bool fromKernelFrame(const struct can_frame& kernel, CanFrame& frame) noexcept {
    if (kernel.can_id & CAN_ERR_FLAG) return false;
    frame = CanFrame{};
    frame.extended = (kernel.can_id & CAN_EFF_FLAG) != 0;
    frame.remote = (kernel.can_id & CAN_RTR_FLAG) != 0;
    frame.id = kernel.can_id & (frame.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
    frame.length = kernel.can_dlc > kMaxDataLength ? kMaxDataLength : kernel.can_dlc;
    if (!frame.remote) std::memcpy(frame.data.data(), kernel.data, frame.length);
    return true;
}

struct can_filter toKernelFilter(const CanFilter& filter) noexcept {
    struct can_filter kernel;
    // Matching on the EFF and RTR flags as well keeps a standard filter from passing extended
    // frames with the same low bits, and remote requests.
    if (filter.extended) {
        kernel.can_id = (filter.id & CAN_EFF_MASK) | CAN_EFF_FLAG;
        kernel.can_mask = (filter.mask & CAN_EFF_MASK) | CAN_EFF_FLAG | CAN_RTR_FLAG;
    } else {
        kernel.can_id = filter.id & CAN_SFF_MASK;
        kernel.can_mask = (filter.mask & CAN_SFF_MASK) | CAN_EFF_FLAG | CAN_RTR_FLAG;
    }
    return kernel;
}

ErrorFrameInfo decodeErrorFrame(const struct can_frame& kernel, ControllerState current) noexcept {
    ErrorFrameInfo info;
    info.state = current;
    auto set = [&info](ControllerState s) {
        info.stateChanged = true;
        info.state = s;
    };
    if (kernel.can_id & CAN_ERR_RESTARTED) set(ControllerState::ErrorActive);
    if (kernel.can_id & CAN_ERR_CRTL) {
        uint8_t controller = kernel.data[1];
        if (controller & (CAN_ERR_CRTL_RX_OVERFLOW | CAN_ERR_CRTL_TX_OVERFLOW))
            info.overflow = true;
        if (controller & CAN_ERR_CRTL_ACTIVE) set(ControllerState::ErrorActive);
        if (controller & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) {
            set(ControllerState::ErrorWarning);
        }
        if (controller & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) {
            set(ControllerState::ErrorPassive);
        }
    }
    if (kernel.can_id & CAN_ERR_BUSOFF) set(ControllerState::BusOff);
    return info;
}

}  // namespace kerf::drivers::can::detail
