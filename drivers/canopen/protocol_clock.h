#pragma once

#include <chrono>

// The time the protocol layers run on, set by whoever runs the cycle: the simulated bus's time in
// simulated runs, the cycle's nominal time (cycle count x period) on a real machine. Timeouts,
// SYNC and heartbeats all read it, so no layer reads a clock of its own.
namespace kerf::drivers::canopen {

class ProtocolClock {
public:
    std::chrono::nanoseconds now() const noexcept { return m_now; }
    void set(std::chrono::nanoseconds now) noexcept { m_now = now; }

private:
    std::chrono::nanoseconds m_now{0};
};

}  // namespace kerf::drivers::canopen
