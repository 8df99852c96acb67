#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/can/can_channel.h"
#include "drivers/can/fixed_queue.h"
#include "drivers/can/frame_observer.h"

// An in-process CAN bus in simulated time. Each attached channel is one controller: its frames
// wait in a transmit queue, the bus arbitrates the queue heads by identifier (lowest wins, as on
// the wire) whenever it falls idle, a frame occupies the bus for its exact bit count at the
// configured bit rate (bitrate 0: no timing) and is then delivered to every other channel, never
// back to its sender. Faults are injected per frame (drop, delay, duplicate) and per controller
// (error passive, bus off). attach() and addFault() run before the simulation; everything else is
// called by the one simulation thread, is noexcept and does not allocate.
namespace kerf::drivers::can {

class VirtualBus;

class VirtualChannel final : public CanChannel {
public:
    std::error_code send(const CanFrame& frame) noexcept override;
    bool receive(CanFrame& frame) noexcept override;
    ControllerState state() const noexcept override { return m_state; }
    const std::string& name() const noexcept { return m_name; }
    uint64_t receiveOverruns() const noexcept { return m_overruns; }

private:
    friend class VirtualBus;
    struct Pending {
        CanFrame frame;
        std::chrono::nanoseconds ready{0};     // may start arbitration from here
        std::chrono::nanoseconds duration{0};  // on the wire
    };
    VirtualChannel(VirtualBus& bus, std::string name) : m_bus(bus), m_name(std::move(name)) {}

    VirtualBus& m_bus;
    std::string m_name;
    ControllerState m_state = ControllerState::ErrorActive;
    FixedQueue<Pending, 64> m_transmit;
    FixedQueue<CanFrame, 256> m_receive;
    uint64_t m_overruns = 0;
};

enum class BusFaultKind : uint8_t {
    Drop,       // the frame is lost: nobody receives it
    Delay,      // the frame enters arbitration `delay` later than it was sent
    Duplicate,  // the frame is transmitted twice
};

// Applies to frames sent with (id & idMask) == id inside [from, until), `count` times (-1: all).
struct BusFault {
    BusFaultKind kind = BusFaultKind::Drop;
    uint32_t id = 0;
    uint32_t idMask = kStandardIdMask;
    std::chrono::nanoseconds from{0};
    std::chrono::nanoseconds until = std::chrono::nanoseconds::max();
    int count = -1;
    std::chrono::nanoseconds delay{0};
};

class VirtualBus {
public:
    explicit VirtualBus(uint32_t bitrate);
    VirtualBus(const VirtualBus&) = delete;
    VirtualBus& operator=(const VirtualBus&) = delete;

    // A new controller on the bus; the reference stays valid as long as the bus.
    VirtualChannel& attach(std::string name);
    // False when the fault table (16 entries) is full.
    bool addFault(const BusFault& fault) noexcept;
    void clearFaults() noexcept { m_faultCount = 0; }
    // Error passive only changes the reported state; bus off also discards the controller's
    // transmit queue, fails its sends and stops its reception until the state is set back.
    void setState(VirtualChannel& channel, ControllerState state) noexcept;
    // Up to four observers see every delivered frame (trace writers, tests).
    bool addObserver(FrameObserver& observer) noexcept;

    // Transmits and delivers every frame whose transmission ends at or before `time`.
    void advanceTo(std::chrono::nanoseconds time) noexcept;
    std::chrono::nanoseconds now() const noexcept { return m_now; }
    // End time of the next transmission, if any frame waits.
    std::optional<std::chrono::nanoseconds> nextDelivery() const noexcept;

    uint32_t bitrate() const noexcept { return m_bitrate; }
    std::chrono::nanoseconds busyTime() const noexcept { return m_busyTime; }
    uint64_t deliveredFrames() const noexcept { return m_delivered; }
    uint64_t droppedFrames() const noexcept { return m_dropped; }

private:
    friend class VirtualChannel;
    struct Next {
        VirtualChannel* sender = nullptr;
        std::chrono::nanoseconds end{0};
    };
    std::error_code enqueue(VirtualChannel& sender, const CanFrame& frame) noexcept;
    std::optional<Next> selectNext() const noexcept;
    void deliver(const Next& next) noexcept;

    uint32_t m_bitrate;
    std::vector<std::unique_ptr<VirtualChannel>> m_channels;
    std::array<BusFault, 16> m_faults{};
    size_t m_faultCount = 0;
    std::array<FrameObserver*, 4> m_observers{};
    size_t m_observerCount = 0;
    std::chrono::nanoseconds m_now{0};
    std::chrono::nanoseconds m_busyUntil{0};
    std::chrono::nanoseconds m_busyTime{0};
    uint64_t m_delivered = 0;
    uint64_t m_dropped = 0;
};

}  // namespace kerf::drivers::can
