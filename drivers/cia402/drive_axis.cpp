#include "drivers/cia402/drive_axis.h"

namespace kerf::drivers::cia402 {

void DriveAxis::configure(Mode mode, std::chrono::nanoseconds stepTimeout) noexcept {
    m_mode = mode;
    m_stepTimeout = stepTimeout;
}

void DriveAxis::setGoal(Goal goal, std::chrono::nanoseconds now) noexcept {
    if (goal == m_goal) return;
    m_goal = goal;
    m_since = now;
}

void DriveAxis::onStatusword(uint16_t statusword, std::chrono::nanoseconds now) noexcept {
    m_statusword = statusword;
    State state = m_state;
    if (!decodeStatusword(statusword, state)) return;
    if (!m_known || state != m_state) m_since = now;
    if ((m_state == State::Fault) != (state == State::Fault)) m_reset = Reset::None;
    m_state = state;
    m_known = true;
}

uint16_t DriveAxis::nextControlword() noexcept {
    uint16_t cw = m_lastControlword;
    if (m_goal == Goal::QuickStop) {
        // Quick stop keeps bits 0, 1, 3: an enabled drive ramps down and holds (0x605A = 6).
        cw = controlwordFor(Command::QuickStop);
    } else if (m_state == State::Fault) {
        // The reset acts on the rising edge of bit 7: one cycle 0x00, then 0x80 until the drive
        // leaves Fault. A fault that persists needs the next explicit request.
        switch (m_reset) {
            case Reset::None:
                cw = 0;
                break;
            case Reset::Low:
                cw = 0;
                m_reset = Reset::High;
                break;
            case Reset::High:
                cw = controlwordFor(Command::FaultReset);
                break;
        }
    } else if (m_state == State::FaultReactionActive || m_state == State::NotReadyToSwitchOn) {
        cw = 0;
    } else {
        State target = m_goal == Goal::Enabled ? State::OperationEnabled : State::SwitchOnDisabled;
        if (m_state == target) {
            cw = m_goal == Goal::Enabled ? controlwordFor(Command::EnableOperation)
                                         : controlwordFor(Command::DisableVoltage);
        } else if (const Transition* t = nextStep(m_state, target)) {
            cw = controlwordFor(t->command);
        }
    }
    m_lastControlword = cw;
    return cw;
}

bool DriveAxis::followsTarget() const noexcept {
    if (m_state != State::OperationEnabled) return false;
    if (m_mode == Mode::CyclicPosition || m_mode == Mode::CyclicVelocity) {
        return (m_statusword & kStatusFollowsTarget) != 0;
    }
    return true;
}

bool DriveAxis::followingError() const noexcept {
    return m_mode == Mode::CyclicPosition && m_state == State::OperationEnabled &&
           (m_statusword & kStatusFollowingError) != 0;
}

bool DriveAxis::stepTimedOut(std::chrono::nanoseconds now) const noexcept {
    if (m_goal != Goal::Enabled || m_state == State::Fault || followsTarget()) return false;
    return now - m_since > m_stepTimeout;
}

}  // namespace kerf::drivers::cia402
