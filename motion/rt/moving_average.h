#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

// Moving average over the last `taps` servo cycles, per channel, in exact integer picometres
// (or pico-degrees), so the output reaches the input exactly when it stands still and the sum
// never drifts. O(channels) per cycle, noexcept, no allocation: RT thread.
namespace kerf::motion {

template <size_t MaxTaps, size_t Channels>
class MovingAverage {
public:
    static constexpr double kScale = 1e9;
    using Values = std::array<double, Channels>;

    void reset(int taps, const Values& value) noexcept {
        m_taps = static_cast<size_t>(taps < 1 ? 1 : taps);
        if (m_taps > MaxTaps) m_taps = MaxTaps;
        m_index = 0;
        m_unchanged = m_taps;
        for (size_t c = 0; c < Channels; ++c) {
            int64_t q = quantise(value[c]);
            for (size_t t = 0; t < m_taps; ++t)
                m_history[t][c] = q;
            m_sum[c] = q * static_cast<int64_t>(m_taps);
        }
    }

    Values push(const Values& value) noexcept {
        Values out{};
        auto& slot = m_history[m_index];
        const auto& newest = m_history[(m_index + m_taps - 1) % m_taps];
        bool changed = false;
        for (size_t c = 0; c < Channels; ++c) {
            if (quantise(value[c]) != newest[c]) changed = true;
        }
        m_unchanged = changed ? 0 : m_unchanged + 1;
        for (size_t c = 0; c < Channels; ++c) {
            int64_t q = quantise(value[c]);
            m_sum[c] += q - slot[c];
            slot[c] = q;
            out[c] = static_cast<double>(m_sum[c]) / (kScale * static_cast<double>(m_taps));
        }
        m_index = (m_index + 1) % m_taps;
        return out;
    }

    // Moves every stored value of one channel (a tool length change re-bases the tip).
    void shift(size_t channel, double delta) noexcept {
        int64_t q = quantise(delta);
        for (size_t t = 0; t < m_taps; ++t)
            m_history[t][channel] += q;
        m_sum[channel] += q * static_cast<int64_t>(m_taps);
    }

    // True when every stored value equals the newest: the output stands still.
    bool settled() const noexcept { return m_unchanged + 1 >= m_taps; }
    size_t taps() const noexcept { return m_taps; }

private:
    static int64_t quantise(double v) noexcept { return std::llround(v * kScale); }

    size_t m_taps = 1;
    size_t m_index = 0;
    size_t m_unchanged = 0;
    std::array<int64_t, Channels> m_sum{};
    std::array<std::array<int64_t, Channels>, MaxTaps> m_history{};
};

}  // namespace kerf::motion
