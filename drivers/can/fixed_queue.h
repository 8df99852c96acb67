#pragma once

#include <array>
#include <cstddef>

// A bounded first-in first-out queue with inline storage for one thread: frame queues of the
// virtual bus and outboxes of the protocol layers. No allocation, no locks; push() fails when full.
namespace kerf::drivers::can {

template <typename T, size_t Capacity>
class FixedQueue {
    static_assert(Capacity > 0 && (Capacity & (Capacity - 1)) == 0, "capacity: a power of two");

public:
    bool push(const T& value) noexcept {
        if (full()) return false;
        m_items[m_head++ & (Capacity - 1)] = value;
        return true;
    }
    bool empty() const noexcept { return m_head == m_tail; }
    bool full() const noexcept { return m_head - m_tail == Capacity; }
    size_t size() const noexcept { return m_head - m_tail; }
    static constexpr size_t capacity() noexcept { return Capacity; }
    // The i-th queued value (0 = front); i < size().
    const T& peek(size_t i) const noexcept { return m_items[(m_tail + i) & (Capacity - 1)]; }
    const T& front() const noexcept { return peek(0); }
    void pop() noexcept { ++m_tail; }
    void clear() noexcept { m_tail = m_head; }

private:
    std::array<T, Capacity> m_items{};
    size_t m_head = 0;
    size_t m_tail = 0;
};

}  // namespace kerf::drivers::can
