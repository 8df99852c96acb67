#include "drivers/canopen/sync_producer.h"

#include "drivers/canopen/cob_id.h"

namespace kerf::drivers::canopen {

void SyncProducer::configure(std::chrono::nanoseconds period, uint8_t counterOverflow) noexcept {
    m_period = period;
    m_overflow = counterOverflow;
}

void SyncProducer::start(std::chrono::nanoseconds now) noexcept {
    m_running = true;
    m_next = now;
    m_counter = 0;
}

can::CanFrame SyncProducer::produce(std::chrono::nanoseconds now) noexcept {
    can::CanFrame f;
    f.id = kSyncId;
    if (m_overflow > 1) {
        m_counter = m_counter >= m_overflow ? 1 : static_cast<uint8_t>(m_counter + 1);
        f.length = 1;
        f.data[0] = m_counter;
    }
    m_next += m_period;
    while (m_next <= now)
        m_next += m_period;
    ++m_count;
    return f;
}

}  // namespace kerf::drivers::canopen
