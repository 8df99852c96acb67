#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>

#include "drivers/can/can_channel.h"

// The SocketCAN back-end: a PF_CAN raw socket bound to one interface (can0, vcan0), non-blocking,
// with receive filters, its own frames not looped back to it, and error frames turned into the
// controller state. open()/close() run in a normal thread before/after the CAN cycle; send(),
// receive() and state() in the cycle's thread (one system call each, no allocation).
namespace kerf::drivers::can {

// Passes frames whose identifier matches `id` in the bits set in `mask`.
struct CanFilter {
    uint32_t id = 0;
    uint32_t mask = 0;
    bool extended = false;
};

// Whether this kernel can open a CAN socket at all: {} or the errno (EAFNOSUPPORT without PF_CAN).
std::error_code probeSocketCan() noexcept;

class SocketCanChannel final : public CanChannel {
public:
    SocketCanChannel() = default;
    ~SocketCanChannel() override;
    SocketCanChannel(const SocketCanChannel&) = delete;
    SocketCanChannel& operator=(const SocketCanChannel&) = delete;

    // Binds to `interface`; no filters receives every frame. The controller state starts from the
    // interface's netlink state where the kernel reports one.
    std::error_code open(std::string_view interface, std::span<const CanFilter> filters = {});
    void close() noexcept;
    bool isOpen() const noexcept { return m_fd >= 0; }

    std::error_code send(const CanFrame& frame) noexcept override;
    bool receive(CanFrame& frame) noexcept override;
    ControllerState state() const noexcept override { return m_state; }

    // Frames the controller or the socket lost (error frames report controller overflows).
    uint64_t overflows() const noexcept { return m_overflows; }
    uint64_t errorFrames() const noexcept { return m_errorFrames; }

private:
    int m_fd = -1;
    ControllerState m_state = ControllerState::Stopped;
    uint64_t m_overflows = 0;
    uint64_t m_errorFrames = 0;
};

}  // namespace kerf::drivers::can
