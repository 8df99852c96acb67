#pragma once

#include <array>
#include <chrono>
#include <cstdint>

#include "drivers/canopen/frame_outbox.h"
#include "drivers/canopen/nmt.h"

// Heartbeat producer (0x1017) and consumer (0x1016) of CiA 301, used by the master and by the
// simulated drives alike. Cycle thread only; noexcept, no allocation.
namespace kerf::drivers::canopen {

// A 0x1016 entry: node-ID in bits 16-23, consumer time in ms in bits 0-15 (0 or node 0: unused).
constexpr uint32_t heartbeatConsumerEntry(uint8_t node, uint16_t timeMs) noexcept {
    return static_cast<uint32_t>(node) << 16 | timeMs;
}

class HeartbeatProducer {
public:
    // Period 0 switches the producer off.
    void configure(uint8_t node, std::chrono::milliseconds period,
                   std::chrono::nanoseconds now) noexcept;
    // Sends the heartbeat when it is due.
    void advance(std::chrono::nanoseconds now, NmtState state, FrameOutbox& out) noexcept;
    bool active() const noexcept { return m_period.count() > 0; }
    std::chrono::nanoseconds next() const noexcept { return m_next; }

private:
    uint8_t m_node = 0;
    std::chrono::nanoseconds m_period{0};
    std::chrono::nanoseconds m_next{0};
};

class HeartbeatConsumer {
public:
    static constexpr size_t kMaxEntries = 16;

    struct Entry {
        uint8_t node = 0;
        std::chrono::nanoseconds timeout{0};
        std::chrono::nanoseconds lastSeen{0};
        NmtState state = NmtState::BootUp;
        bool heard = false;     // a heartbeat arrived since arm()
        bool armed = false;     // supervising
        bool timedOut = false;  // latched until the next arm()
    };

    // Sets entry `slot` from a 0x1016 value; false for a slot out of range.
    bool configure(size_t slot, uint32_t entry) noexcept;
    uint32_t entryValue(size_t slot) const noexcept;
    // Starts supervising the entry of `node` at `now`: a heartbeat must come within its time.
    // CiA 301 starts at the first heartbeat; the master arms at the start command instead, so a
    // node that never speaks is caught too.
    void arm(uint8_t node, std::chrono::nanoseconds now) noexcept;
    void disarm(uint8_t node) noexcept;
    // A heartbeat frame; returns the entry it belongs to, or nullptr.
    const Entry* onHeartbeat(uint8_t node, NmtState state, std::chrono::nanoseconds now) noexcept;
    // Entries that time out now, one per call (nullptr when none): the caller loops.
    const Entry* nextTimeout(std::chrono::nanoseconds now) noexcept;
    const Entry* find(uint8_t node) const noexcept;

private:
    Entry* findEntry(uint8_t node) noexcept;
    std::array<Entry, kMaxEntries> m_entries{};
};

}  // namespace kerf::drivers::canopen
