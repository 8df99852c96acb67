#include "drivers/canopen/heartbeat.h"

namespace kerf::drivers::canopen {

void HeartbeatProducer::configure(uint8_t node, std::chrono::milliseconds period,
                                  std::chrono::nanoseconds now) noexcept {
    m_node = node;
    m_period = period;
    m_next = now + m_period;
}

void HeartbeatProducer::advance(std::chrono::nanoseconds now, NmtState state,
                                FrameOutbox& out) noexcept {
    if (m_period.count() <= 0 || now < m_next) return;
    out.push(heartbeatFrame(m_node, state));
    m_next += m_period;
    if (m_next <= now) m_next = now + m_period;  // after a pause: no burst of late heartbeats
}

bool HeartbeatConsumer::configure(size_t slot, uint32_t entry) noexcept {
    if (slot >= m_entries.size()) return false;
    Entry& e = m_entries[slot];
    e = Entry{};
    e.node = static_cast<uint8_t>(entry >> 16);
    e.timeout = std::chrono::milliseconds(entry & 0xFFFF);
    return true;
}

uint32_t HeartbeatConsumer::entryValue(size_t slot) const noexcept {
    if (slot >= m_entries.size()) return 0;
    const Entry& e = m_entries[slot];
    auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(e.timeout).count();
    return heartbeatConsumerEntry(e.node, static_cast<uint16_t>(ms));
}

HeartbeatConsumer::Entry* HeartbeatConsumer::findEntry(uint8_t node) noexcept {
    if (node == 0) return nullptr;
    for (Entry& e : m_entries) {
        if (e.node == node && e.timeout.count() > 0) return &e;
    }
    return nullptr;
}

const HeartbeatConsumer::Entry* HeartbeatConsumer::find(uint8_t node) const noexcept {
    return const_cast<HeartbeatConsumer*>(this)->findEntry(node);
}

void HeartbeatConsumer::arm(uint8_t node, std::chrono::nanoseconds now) noexcept {
    if (Entry* e = findEntry(node)) {
        e->armed = true;
        e->heard = false;
        e->timedOut = false;
        e->lastSeen = now;
    }
}

void HeartbeatConsumer::disarm(uint8_t node) noexcept {
    if (Entry* e = findEntry(node)) e->armed = false;
}

const HeartbeatConsumer::Entry* HeartbeatConsumer::onHeartbeat(
    uint8_t node, NmtState state, std::chrono::nanoseconds now) noexcept {
    Entry* e = findEntry(node);
    if (!e) return nullptr;
    e->lastSeen = now;
    e->state = state;
    e->heard = true;
    return e;
}

const HeartbeatConsumer::Entry* HeartbeatConsumer::nextTimeout(
    std::chrono::nanoseconds now) noexcept {
    for (Entry& e : m_entries) {
        if (e.armed && !e.timedOut && e.timeout.count() > 0 && now - e.lastSeen > e.timeout) {
            e.timedOut = true;
            return &e;
        }
    }
    return nullptr;
}

}  // namespace kerf::drivers::canopen
