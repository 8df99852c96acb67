#pragma once

#include <atomic>
#include <cstring>
#include <type_traits>

// Single-writer snapshot: write() never blocks (RT-safe); read() retries while a write is in
// progress (readers are normal threads).
namespace kerf::motion {

template <typename T>
class Seqlock {
    static_assert(std::is_trivially_copyable_v<T>);

public:
    void write(const T& value) noexcept {
        unsigned seq = m_sequence.load(std::memory_order_relaxed);
        m_sequence.store(seq + 1, std::memory_order_relaxed);
        std::atomic_thread_fence(std::memory_order_release);
        copyIn(value);
        std::atomic_thread_fence(std::memory_order_release);
        m_sequence.store(seq + 2, std::memory_order_relaxed);
    }
    T read() const noexcept {
        T out;
        for (;;) {
            unsigned before = m_sequence.load(std::memory_order_acquire);
            if (before & 1u) continue;
            copyOut(out);
            std::atomic_thread_fence(std::memory_order_acquire);
            if (m_sequence.load(std::memory_order_relaxed) == before) return out;
        }
    }

private:
    // Word-wise relaxed atomic copies keep the data race defined behaviour.
    static constexpr size_t kWords =
        (sizeof(T) + sizeof(unsigned long) - 1) / sizeof(unsigned long);
    void copyIn(const T& value) noexcept {
        unsigned long words[kWords] = {};
        std::memcpy(words, &value, sizeof(T));
        for (size_t i = 0; i < kWords; ++i)
            m_data[i].store(words[i], std::memory_order_relaxed);
    }
    void copyOut(T& out) const noexcept {
        unsigned long words[kWords];
        for (size_t i = 0; i < kWords; ++i)
            words[i] = m_data[i].load(std::memory_order_relaxed);
        std::memcpy(&out, words, sizeof(T));
    }

    std::atomic<unsigned> m_sequence{0};
    std::atomic<unsigned long> m_data[kWords] = {};
};

}  // namespace kerf::motion
