#pragma once

#include <chrono>
#include <cstdint>

#include "drivers/can/can_frame.h"

// The SYNC producer (COB-ID 0x080, 0x1005 = 0x40000080 on the master): one frame per
// communication cycle period (0x1006). With a counter overflow value (0x1019) above 1 the frame
// carries a counter 1..overflow; otherwise it has no data. Cycle thread only.
namespace kerf::drivers::canopen {

class SyncProducer {
public:
    void configure(std::chrono::nanoseconds period, uint8_t counterOverflow = 0) noexcept;
    void start(std::chrono::nanoseconds now) noexcept;
    void stop() noexcept { m_running = false; }
    bool running() const noexcept { return m_running; }
    bool due(std::chrono::nanoseconds now) const noexcept { return m_running && now >= m_next; }
    // The SYNC frame of this cycle; the next one is due one period later (cycles missed by a late
    // caller are skipped, not sent in a burst).
    can::CanFrame produce(std::chrono::nanoseconds now) noexcept;
    std::chrono::nanoseconds period() const noexcept { return m_period; }
    uint64_t produced() const noexcept { return m_count; }

private:
    std::chrono::nanoseconds m_period{std::chrono::milliseconds(1)};
    std::chrono::nanoseconds m_next{0};
    uint8_t m_overflow = 0;
    uint8_t m_counter = 0;
    bool m_running = false;
    uint64_t m_count = 0;
};

}  // namespace kerf::drivers::canopen
