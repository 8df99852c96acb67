#pragma once

#include <chrono>
#include <cstdint>

#include "drivers/cia402/state_machine.h"

// The master's side of one CiA 402 drive: it reads the statusword of every TPDO and decides the
// controlword of every RPDO so that the drive reaches the goal one confirmed transition at a
// time (a step that the statusword does not confirm within the step timeout is reported), with
// the fault reset as an explicit request (0x00, then the 0x80 edge). Cycle thread only.
namespace kerf::drivers::cia402 {

enum class Mode : int8_t {
    ProfilePosition = 1,
    ProfileVelocity = 3,
    Homing = 6,
    CyclicPosition = 8,
    CyclicVelocity = 9,
};

enum class Goal : uint8_t { Disabled, Enabled, QuickStop };

class DriveAxis {
public:
    void configure(Mode mode, std::chrono::nanoseconds stepTimeout) noexcept;
    Mode mode() const noexcept { return m_mode; }

    void setGoal(Goal goal, std::chrono::nanoseconds now) noexcept;
    // Restarts the step timer (the node just became operational).
    void restartTimer(std::chrono::nanoseconds now) noexcept { m_since = now; }
    Goal goal() const noexcept { return m_goal; }
    // In Fault: the next controlwords reset it (once; a request outside Fault does nothing).
    void requestFaultReset() noexcept {
        if (m_state == State::Fault) m_reset = Reset::Low;
    }

    // The statusword of a TPDO.
    void onStatusword(uint16_t statusword, std::chrono::nanoseconds now) noexcept;
    // The controlword for the next RPDO.
    uint16_t nextControlword() noexcept;

    State state() const noexcept { return m_state; }
    uint16_t statusword() const noexcept { return m_statusword; }
    // Operation enabled and, in the cyclic modes, statusword bit 12: the drive follows targets.
    bool followsTarget() const noexcept;
    // The drive reports a following error (CSP, bit 13).
    bool followingError() const noexcept;
    // The goal is Enabled, no fault, and the state did not change for longer than the step
    // timeout.
    bool stepTimedOut(std::chrono::nanoseconds now) const noexcept;

private:
    Mode m_mode = Mode::CyclicPosition;
    std::chrono::nanoseconds m_stepTimeout{std::chrono::milliseconds(500)};
    Goal m_goal = Goal::Disabled;
    State m_state = State::NotReadyToSwitchOn;
    uint16_t m_statusword = 0;
    bool m_known = false;
    enum class Reset : uint8_t { None, Low, High };
    Reset m_reset = Reset::None;
    uint16_t m_lastControlword = 0;
    std::chrono::nanoseconds m_since{0};  // state or goal last changed
};

}  // namespace kerf::drivers::cia402
