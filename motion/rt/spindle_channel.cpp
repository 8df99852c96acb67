#include "motion/rt/spindle_channel.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::motion {

void SpindleChannel::configure(const MachineModel& model) noexcept {
    m_limits = {model.options.spindleAccelRevPerS2 * 360.0,
                model.options.spindleJerkRevPerS3 * 360.0};
    m_maxRpm = model.spindleMaxRpm;
}

void SpindleChannel::reset(double angleDeg) noexcept {
    m_angle = angleDeg;
    m_velocity = 0.0;
    m_mode = Mode::Speed;
    m_gen.reset(angleDeg);
}

void SpindleChannel::command(int direction, double rpm, double surfaceSpeedMPerMin,
                             double maxRpm) noexcept {
    m_direction = direction;
    m_rpm = rpm;
    m_surfaceSpeed = surfaceSpeedMPerMin;
    m_cssMaxRpm = maxRpm > 0.0 ? maxRpm : m_maxRpm;
    m_commandApplied = false;
    if (m_mode == Mode::Orient) m_mode = Mode::Speed;
}

void SpindleChannel::orient(double angleDeg) noexcept {
    m_mode = Mode::Orient;
    m_orientTarget = angleDeg;
    m_orientPlaced = false;
    m_gen.setState({m_angle, m_velocity, m_gen.state().a});
}

void SpindleChannel::unlock() noexcept {
    m_mode = Mode::Speed;
    m_gen.setState({m_angle, m_velocity, 0.0});
}

void SpindleChannel::setLockedAngle(double angleDeg, double velocityDegPerS) noexcept {
    m_angle = angleDeg;
    m_velocity = velocityDegPerS;
}

bool SpindleChannel::settled() const noexcept {
    switch (m_mode) {
        case Mode::Locked:
            return true;
        case Mode::Orient:
            return m_orientPlaced && m_gen.atRest() && std::fabs(m_angle - m_orientGoal) < 1e-6;
        case Mode::Speed:
            return m_commandApplied && std::fabs(m_velocity - m_targetVelocity) < 1e-6 &&
                   std::fabs(m_gen.state().a) < 1e-6;
    }
    return true;
}

void SpindleChannel::update(double dt, double radiusMm) noexcept {
    if (m_mode == Mode::Locked) return;
    if (m_mode == Mode::Orient) {
        // Stop first, then turn forwards to the next angle equal to the target modulo 360.
        if (!m_orientPlaced) {
            if (m_gen.atRest()) {
                double ahead = std::fmod(std::fmod(m_orientTarget - m_angle, 360.0) + 360.0, 360.0);
                m_orientGoal = m_angle + ahead;
                m_orientPlaced = true;
            } else {
                m_gen.step(dt, 0.0, m_limits, {});
            }
        }
        if (m_orientPlaced) {
            Constraint stop{m_orientGoal, 0.0};
            m_gen.step(dt, std::min(m_maxRpm, 60.0) * 6.0, m_limits, {&stop, 1});
            if (m_gen.state().s >= m_orientGoal - 1e-9 && m_gen.atRest()) {
                m_gen.setState({m_orientGoal, 0.0, 0.0});
            }
        }
        m_angle = m_gen.state().s;
        m_velocity = m_gen.state().v;
        m_targetVelocity = 0.0;
        return;
    }
    double rpm = m_rpm;
    if (m_surfaceSpeed > 0.0 && radiusMm > 1e-6) {
        rpm = m_surfaceSpeed * 1000.0 / (kTwoPi * radiusMm);
        rpm = std::min(rpm, m_cssMaxRpm);
    }
    rpm = std::min(rpm * m_override, m_maxRpm);
    m_targetVelocity = m_direction * rpm * 6.0;
    m_commandApplied = true;
    m_gen.step(dt, m_targetVelocity, m_limits, {});
    m_velocity = m_gen.state().v;
    m_angle = m_gen.state().s;
}

}  // namespace kerf::motion
