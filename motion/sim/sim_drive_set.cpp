#include "motion/sim/sim_drive_set.h"

#include <algorithm>
#include <cmath>

namespace kerf::motion {

SimDriveSet::SimDriveSet(const MachineModel& model, const SimDriveOptions& options)
    : m_model(model), m_options(options), m_count(model.jointCount) {
    m_state.fill(DriveState::Disabled);
}

void SimDriveSet::setTruePositions(const std::array<double, kMaxJoints>& positions) {
    m_true = positions;
    m_setpoint = positions;
    m_previousSetpoint = positions;
}

double SimDriveSet::reportedPosition(int joint) const noexcept {
    return m_true[static_cast<size_t>(joint)] + m_offset[static_cast<size_t>(joint)];
}

void SimDriveSet::injectFault(int joint, uint16_t code) noexcept {
    m_state[static_cast<size_t>(joint)] = DriveState::Fault;
    m_fault[static_cast<size_t>(joint)] = code;
}

BusResult SimDriveSet::read(std::span<JointFeedback> feedback) noexcept {
    for (int j = 0; j < m_count && j < static_cast<int>(feedback.size()); ++j) {
        auto i = static_cast<size_t>(j);
        JointFeedback& fb = feedback[i];
        fb.position = reportedPosition(j);
        fb.state = m_state[i];
        fb.faultCode = m_fault[i];
        int axis = m_model.jointAxis[i];
        fb.homeSwitch = axis >= 0 && m_true[i] <= m_model.axes[static_cast<size_t>(axis)].home;
        fb.probeLatched = m_latched;
        fb.probePosition = m_latch[i] + m_offset[i];
    }
    m_latched = false;
    return BusResult::Ok;
}

BusResult SimDriveSet::write(std::span<const JointSetpoint> setpoints) noexcept {
    for (int j = 0; j < m_count && j < static_cast<int>(setpoints.size()); ++j) {
        auto i = static_cast<size_t>(j);
        m_previousSetpoint[i] =
            m_haveSetpoint ? m_setpoint[i] : setpoints[i].position - m_offset[i];
        m_setpoint[i] = setpoints[i].position - m_offset[i];
    }
    m_haveSetpoint = true;
    return BusResult::Ok;
}

void SimDriveSet::request(DriveRequest request) noexcept {
    switch (request) {
        case DriveRequest::Enable:
            for (int j = 0; j < m_count; ++j) {
                auto i = static_cast<size_t>(j);
                if (m_state[i] != DriveState::Fault) m_state[i] = DriveState::Enabling;
            }
            m_enableCountdown = m_options.enableCycles;
            m_haveSetpoint = false;
            break;
        case DriveRequest::Disable:
            std::fill(m_state.begin(), m_state.begin() + m_count, DriveState::Disabled);
            break;
        case DriveRequest::QuickStop:
            for (int j = 0; j < m_count; ++j) {
                auto i = static_cast<size_t>(j);
                if (m_state[i] == DriveState::Enabled) m_state[i] = DriveState::QuickStop;
            }
            break;
        case DriveRequest::FaultReset:
            for (int j = 0; j < m_count; ++j) {
                auto i = static_cast<size_t>(j);
                if (m_state[i] == DriveState::Fault || m_state[i] == DriveState::QuickStop) {
                    m_state[i] = DriveState::Disabled;
                    m_fault[i] = 0;
                }
            }
            break;
    }
}

void SimDriveSet::setPosition(int joint, double position) noexcept {
    auto i = static_cast<size_t>(joint);
    m_offset[i] = position - m_true[i];
}

void SimDriveSet::armProbe(bool armed) noexcept {
    m_probeArmed = armed;
    m_probeWasHit = false;
}

void SimDriveSet::advance(double dt) noexcept {
    if (m_enableCountdown >= 0 && m_enableCountdown-- == 0) {
        for (int j = 0; j < m_count; ++j) {
            auto i = static_cast<size_t>(j);
            if (m_state[i] == DriveState::Enabling) m_state[i] = DriveState::Enabled;
        }
    }
    std::array<double, kMaxJoints> before = m_true;
    for (int j = 0; j < m_count; ++j) {
        auto i = static_cast<size_t>(j);
        switch (m_state[i]) {
            case DriveState::Enabled: {
                double ff = (m_setpoint[i] - m_previousSetpoint[i]) / dt * m_options.feedForward;
                double v = ff + m_options.positionGainPerS * (m_setpoint[i] - m_true[i]);
                m_velocity[i] = v;
                m_true[i] += v * dt;
                break;
            }
            case DriveState::QuickStop: {
                double dv = m_options.quickStopDecel * dt;
                double v = m_velocity[i];
                v = v > 0.0 ? std::max(0.0, v - dv) : std::min(0.0, v + dv);
                m_velocity[i] = v;
                m_true[i] += v * dt;
                break;
            }
            default:
                m_velocity[i] = 0.0;
                break;
        }
    }
    if (m_probeArmed) {
        // Without a workpiece the probe never touches.
        const bool touchWanted = m_probeEvent == ProbeEvent::Touch;
        auto hit = [&](const std::array<double, kMaxJoints>& joints) {
            return (m_probeSurface && m_probeSurface(joints)) == touchWanted;
        };
        bool nowHit = hit(m_true);
        if (nowHit && !m_probeWasHit) {
            // Touch probe latch: find the crossing inside the period by bisection (the joints
            // move linearly within a period in this model, so the crossing is exact).
            double lo = 0.0;
            double hi = 1.0;
            std::array<double, kMaxJoints> p{};
            for (int k = 0; k < 40; ++k) {
                double mid = (lo + hi) / 2.0;
                for (size_t i = 0; i < p.size(); ++i)
                    p[i] = before[i] + (m_true[i] - before[i]) * mid;
                if (hit(p))
                    hi = mid;
                else
                    lo = mid;
            }
            for (size_t i = 0; i < p.size(); ++i)
                m_latch[i] = before[i] + (m_true[i] - before[i]) * hi;
            m_latched = true;
            m_probeArmed = false;
        }
        m_probeWasHit = nowHit;
    }
}

}  // namespace kerf::motion
