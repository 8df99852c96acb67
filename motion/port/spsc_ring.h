#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <new>

// Bounded lock-free single-producer single-consumer ring of fixed-size values. push() from the
// producer thread only; front()/peek()/pop() from the consumer thread only; size() from either.
// No allocation after construction (the storage is inline: place large rings on the heap before
// the RT thread starts). Belongs in core/base once the task layer needs it too.
namespace kerf::motion {

template <typename T, size_t Capacity>
class SpscRing {
    static_assert((Capacity & (Capacity - 1)) == 0, "capacity must be a power of two");

public:
    bool push(const T& value) noexcept {
        size_t head = m_head.load(std::memory_order_relaxed);
        if (head - m_tail.load(std::memory_order_acquire) == Capacity) return false;
        m_items[head & (Capacity - 1)] = value;
        m_head.store(head + 1, std::memory_order_release);
        return true;
    }
    size_t size() const noexcept {
        return m_head.load(std::memory_order_acquire) - m_tail.load(std::memory_order_acquire);
    }
    bool empty() const noexcept { return size() == 0; }
    bool full() const noexcept { return size() == Capacity; }
    static constexpr size_t capacity() noexcept { return Capacity; }
    // The i-th queued value (0 = front); i < size().
    const T& peek(size_t i) const noexcept {
        return m_items[(m_tail.load(std::memory_order_relaxed) + i) & (Capacity - 1)];
    }
    const T& front() const noexcept { return peek(0); }
    void pop() noexcept {
        m_tail.store(m_tail.load(std::memory_order_relaxed) + 1, std::memory_order_release);
    }
    // Consumer side: drops everything queued.
    void clear() noexcept { m_tail.store(m_head.load(std::memory_order_acquire)); }

private:
    alignas(64) std::atomic<size_t> m_head{0};
    alignas(64) std::atomic<size_t> m_tail{0};
    std::array<T, Capacity> m_items{};
};

}  // namespace kerf::motion
