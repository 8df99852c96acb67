#include "drivers/can/virtual_bus.h"

#include "drivers/can/bit_timing.h"

namespace kerf::drivers::can {

namespace {

// Arbitration order of ISO 11898-1: the identifier bits, then RTR (standard) or SRR (extended),
// then IDE, then the extension and its RTR; a dominant 0 wins, so the lower key wins.
uint64_t arbitrationKey(const CanFrame& f) noexcept {
    uint64_t base = f.extended ? (f.id >> 18) & 0x7FF : f.id & kStandardIdMask;
    uint64_t key = base << 21;
    key |= static_cast<uint64_t>(f.extended || f.remote) << 20;
    key |= static_cast<uint64_t>(f.extended) << 19;
    if (f.extended) key |= static_cast<uint64_t>(f.id & 0x3FFFF) << 1 | (f.remote ? 1u : 0u);
    return key;
}

}  // namespace

std::error_code VirtualChannel::send(const CanFrame& frame) noexcept {
    return m_bus.enqueue(*this, frame);
}

bool VirtualChannel::receive(CanFrame& frame) noexcept {
    if (m_receive.empty()) return false;
    frame = m_receive.front();
    m_receive.pop();
    return true;
}

VirtualBus::VirtualBus(uint32_t bitrate) : m_bitrate(bitrate) {}

VirtualChannel& VirtualBus::attach(std::string name) {
    m_channels.push_back(
        std::unique_ptr<VirtualChannel>(new VirtualChannel(*this, std::move(name))));
    return *m_channels.back();
}

bool VirtualBus::addFault(const BusFault& fault) noexcept {
    if (m_faultCount == m_faults.size()) return false;
    m_faults[m_faultCount++] = fault;
    return true;
}

bool VirtualBus::addObserver(FrameObserver& observer) noexcept {
    if (m_observerCount == m_observers.size()) return false;
    m_observers[m_observerCount++] = &observer;
    return true;
}

void VirtualBus::setState(VirtualChannel& channel, ControllerState state) noexcept {
    channel.m_state = state;
    if (state == ControllerState::BusOff || state == ControllerState::Stopped) {
        channel.m_transmit.clear();
    }
}

std::error_code VirtualBus::enqueue(VirtualChannel& sender, const CanFrame& frame) noexcept {
    if (sender.m_state == ControllerState::BusOff || sender.m_state == ControllerState::Stopped) {
        return std::make_error_code(std::errc::network_down);
    }
    VirtualChannel::Pending pending{frame, m_now, frameDuration(frame, m_bitrate)};
    int copies = 1;
    for (size_t i = 0; i < m_faultCount; ++i) {
        BusFault& f = m_faults[i];
        if ((frame.id & f.idMask) != f.id || m_now < f.from || m_now >= f.until || f.count == 0) {
            continue;
        }
        if (f.count > 0) --f.count;
        switch (f.kind) {
            case BusFaultKind::Drop:
                copies = 0;
                break;
            case BusFaultKind::Delay:
                pending.ready += f.delay;
                break;
            case BusFaultKind::Duplicate:
                copies = 2;
                break;
        }
        break;
    }
    if (copies == 0) {
        ++m_dropped;
        return {};
    }
    if (sender.m_transmit.size() + static_cast<size_t>(copies) > sender.m_transmit.capacity()) {
        return std::make_error_code(std::errc::no_buffer_space);
    }
    for (int i = 0; i < copies; ++i)
        sender.m_transmit.push(pending);
    return {};
}

std::optional<VirtualBus::Next> VirtualBus::selectNext() const noexcept {
    bool any = false;
    std::chrono::nanoseconds earliest = std::chrono::nanoseconds::max();
    for (const auto& c : m_channels) {
        if (c->m_transmit.empty()) continue;
        any = true;
        if (c->m_transmit.front().ready < earliest) earliest = c->m_transmit.front().ready;
    }
    if (!any) return std::nullopt;
    std::chrono::nanoseconds start = earliest > m_busyUntil ? earliest : m_busyUntil;
    const VirtualChannel::Pending* best = nullptr;
    Next next;
    for (const auto& c : m_channels) {
        if (c->m_transmit.empty()) continue;
        const VirtualChannel::Pending& head = c->m_transmit.front();
        if (head.ready > start) continue;
        if (!best || arbitrationKey(head.frame) < arbitrationKey(best->frame)) {
            best = &head;
            next.sender = c.get();
        }
    }
    next.end = start + best->duration;
    return next;
}

std::optional<std::chrono::nanoseconds> VirtualBus::nextDelivery() const noexcept {
    std::optional<Next> next = selectNext();
    if (!next) return std::nullopt;
    return next->end;
}

void VirtualBus::deliver(const Next& next) noexcept {
    CanFrame frame = next.sender->m_transmit.front().frame;
    m_busyTime += next.sender->m_transmit.front().duration;
    next.sender->m_transmit.pop();
    m_busyUntil = next.end;
    ++m_delivered;
    for (const auto& c : m_channels) {
        if (c.get() == next.sender || c->m_state == ControllerState::BusOff ||
            c->m_state == ControllerState::Stopped) {
            continue;
        }
        if (!c->m_receive.push(frame)) ++c->m_overruns;
    }
    for (size_t i = 0; i < m_observerCount; ++i)
        m_observers[i]->onFrame(next.end, frame);
}

void VirtualBus::advanceTo(std::chrono::nanoseconds time) noexcept {
    while (std::optional<Next> next = selectNext()) {
        if (next->end > time) break;
        deliver(*next);
    }
    if (time > m_now) m_now = time;
}

}  // namespace kerf::drivers::can
