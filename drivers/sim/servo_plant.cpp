#include "drivers/sim/servo_plant.h"

#include <algorithm>
#include <cmath>

namespace kerf::drivers::sim {

void ServoPlant::reset(double position) noexcept {
    m_x = m_from = m_to = m_command = position;
    m_v = m_velocityCommand = m_velocityTarget = 0.0;
    m_control = Control::Off;
    m_rampDone = false;
}

void ServoPlant::interpolateTo(double target, double periodS) noexcept {
    if (m_control != Control::Position) {
        m_command = m_x;
        m_control = Control::Position;
    }
    m_from = m_command;
    m_to = target;
    m_period = periodS;
    m_elapsed = 0.0;
}

void ServoPlant::velocityTo(double velocity, double accel) noexcept {
    if (m_control != Control::Velocity) m_velocityCommand = m_v;
    m_control = Control::Velocity;
    m_velocityTarget = velocity;
    m_accel = accel;
}

void ServoPlant::rampDown(double decel, bool holdAfter) noexcept {
    if (m_control == Control::Ramp) return;
    m_control = Control::Ramp;
    m_velocityCommand = m_v;
    m_accel = decel;
    m_holdAfterRamp = holdAfter;
    m_rampDone = false;
}

void ServoPlant::hold() noexcept {
    m_control = Control::Position;
    m_from = m_to = m_command = m_x;
    m_period = 0.0;
}

void ServoPlant::step(double h) noexcept {
    double velocityCommand = 0.0;
    switch (m_control) {
        case Control::Off: {
            // No torque: friction slows the axis down.
            double dv = m_p.frictionDecel * h;
            m_v = std::fabs(m_v) <= dv ? 0.0 : m_v - std::copysign(dv, m_v);
            m_x += (m_v + m_drift) * h;
            return;
        }
        case Control::Position: {
            // The command's own velocity over this step is fed forward.
            double before = m_command;
            m_elapsed += h;
            m_command = m_period > 0.0 && m_elapsed < m_period
                            ? m_from + (m_to - m_from) * (m_elapsed / m_period)
                            : m_to;
            double feedForward = (m_command - before) / h;
            // Error and position at the start of the step, where both are known.
            velocityCommand = feedForward + m_p.positionGainPerS * (before - m_x);
            break;
        }
        case Control::Velocity: {
            if (m_accel <= 0.0) {
                m_velocityCommand = m_velocityTarget;
            } else {
                double dv = m_accel * h;
                double gap = m_velocityTarget - m_velocityCommand;
                m_velocityCommand = std::fabs(gap) <= dv
                                        ? m_velocityTarget
                                        : m_velocityCommand + std::copysign(dv, gap);
            }
            velocityCommand = m_velocityCommand;
            m_command = m_x;
            break;
        }
        case Control::Ramp: {
            double dv = m_accel * h;
            m_velocityCommand = std::fabs(m_velocityCommand) <= dv
                                    ? 0.0
                                    : m_velocityCommand - std::copysign(dv, m_velocityCommand);
            velocityCommand = m_velocityCommand;
            m_command = m_x;
            // Stopped once the rest of the speed can go within one step at full acceleration.
            if (m_velocityCommand == 0.0 && std::fabs(m_v) <= m_p.maxAcceleration * h) {
                m_v = 0.0;
                m_rampDone = true;
                if (m_holdAfterRamp) {
                    hold();
                } else {
                    m_control = Control::Off;
                }
                return;
            }
            break;
        }
    }
    if (m_drift != 0.0) {
        // Overloaded: the external force wins over the motor, the axis goes where it is pushed.
        m_v = 0.0;
        m_a = 0.0;
        m_x += m_drift * h;
        return;
    }
    velocityCommand = std::clamp(velocityCommand, -m_p.maxVelocity, m_p.maxVelocity);
    double accel = (velocityCommand - m_v) / std::max(m_p.velocityLagS, h);
    accel = std::clamp(accel, -m_p.maxAcceleration, m_p.maxAcceleration);
    m_v += accel * h;
    m_a = accel;
    m_x += m_v * h;
}

void ServoPlant::advance(double dt) noexcept {
    while (dt > 1e-12) {
        double h = std::min(dt, m_p.stepS);
        step(h);
        dt -= h;
    }
}

}  // namespace kerf::drivers::sim
