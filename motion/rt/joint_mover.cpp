#include "motion/rt/joint_mover.h"

#include <cmath>

namespace kerf::motion {

void JointMover::jog(int axis, double position, double velocity, double lo, double hi) noexcept {
    m_axis = axis;
    m_active = true;
    m_continuous = true;
    m_stopping = false;
    m_origin = position;
    m_direction = velocity >= 0.0 ? 1.0 : -1.0;
    m_velocity = std::fabs(velocity);
    m_target = velocity >= 0.0 ? hi : lo;
    m_gen.reset(0.0);
}

void JointMover::moveTo(int axis, double position, double target, double velocity) noexcept {
    m_axis = axis;
    m_active = true;
    m_continuous = false;
    m_stopping = false;
    m_origin = position;
    m_direction = target >= position ? 1.0 : -1.0;
    m_velocity = std::fabs(velocity);
    m_target = target;
    m_gen.reset(0.0);
}

bool JointMover::update(double dt, const Limits& limits, double& position) noexcept {
    if (!m_active) return false;
    double ahead = (m_target - m_origin) * m_direction;  // target along the motion
    if (m_gen.atRest() && !m_continuous && ahead < m_gen.state().s) {
        // The handwheel went back: turn round from here.
        m_origin += m_direction * m_gen.state().s;
        m_direction = -m_direction;
        m_gen.reset(0.0);
        ahead = (m_target - m_origin) * m_direction;
    }
    Constraint stopAt{ahead, 0.0};
    double targetVelocity = m_stopping ? 0.0 : m_velocity;
    if (ahead < m_gen.state().s) targetVelocity = 0.0;
    m_gen.step(dt, targetVelocity, limits, {&stopAt, 1});
    MotionState x = m_gen.state();
    if (x.s >= ahead - 1e-9 && m_gen.atRest()) m_gen.setState({ahead, 0.0, 0.0});
    position = m_origin + m_direction * m_gen.state().s;
    bool done = m_gen.atRest() && (m_stopping || std::fabs(m_gen.state().s - ahead) < 1e-9);
    if (done) m_active = false;
    return m_active;
}

}  // namespace kerf::motion
