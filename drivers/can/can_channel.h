#pragma once

#include <cstdint>
#include <system_error>

#include "drivers/can/can_frame.h"

// A CAN interface as the protocol layers see it: non-blocking send and receive of frames and the
// controller's error state. Implemented by SocketCAN, the in-process virtual bus and the UDP bus.
// All functions are called from the one thread that runs the CAN cycle; they never block, never
// allocate and never throw.
namespace kerf::drivers::can {

// ISO 11898-1 fault confinement states, plus Stopped for a controller that is down.
enum class ControllerState : uint8_t { ErrorActive, ErrorWarning, ErrorPassive, BusOff, Stopped };

class CanChannel {
public:
    virtual ~CanChannel() = default;
    // Queues one frame. Errors: no_buffer_space (transmit queue full), network_down (bus off or
    // controller stopped), not_connected (channel not open).
    virtual std::error_code send(const CanFrame& frame) noexcept = 0;
    // Takes the next received frame into `frame`; false when none is waiting.
    virtual bool receive(CanFrame& frame) noexcept = 0;
    virtual ControllerState state() const noexcept = 0;
};

}  // namespace kerf::drivers::can
