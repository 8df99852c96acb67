#pragma once

// The mechanics and control loops of a simulated servo axis, in drive units (counts): a
// position loop (gain kp, with the interpolated target's velocity fed forward) commands a
// velocity loop, modelled as a first-order lag with time constant tau, whose output is limited
// in velocity and acceleration (current limit). CSP targets are interpolated linearly over the
// interpolation period, as a CiA 402 drive does between SYNCs. Quick stop and fault reaction
// ramp the velocity down with their deceleration; torque off lets the axis coast with friction.
// An overload (an external force stronger than the motor) pushes the axis at a drift velocity
// whatever the loops command: the following error grows until the drive trips. Simulation thread.
namespace kerf::drivers::sim {

struct PlantParameters {
    double positionGainPerS = 150.0;
    double velocityLagS = 0.001;
    double maxVelocity = 1.0e7;      // counts/s
    double maxAcceleration = 1.0e8;  // counts/s^2
    double frictionDecel = 1.0e6;    // counts/s^2, coasting without torque
    double stepS = 125e-6;           // integration step (8 kHz current/velocity loop)
};

class ServoPlant {
public:
    enum class Control { Off, Position, Velocity, Ramp };

    void configure(const PlantParameters& parameters) noexcept { m_p = parameters; }
    void reset(double position) noexcept;

    // CSP: move the command from where it is to `target` over `periodS`.
    void interpolateTo(double target, double periodS) noexcept;
    // CSV (accel 0: at once) or PV (ramp with accel counts/s^2) to `velocity`.
    void velocityTo(double velocity, double accel) noexcept;
    // Ramp the velocity to zero with `decel`, then hold the position (or switch torque off).
    void rampDown(double decel, bool holdAfter) noexcept;
    // Hold the current position (quick stop done, or operation enabled without a target yet).
    void hold() noexcept;
    void torqueOff() noexcept { m_control = Control::Off; }

    void advance(double dt) noexcept;

    Control control() const noexcept { return m_control; }
    double position() const noexcept { return m_x; }
    double velocity() const noexcept { return m_v; }
    double command() const noexcept { return m_command; }
    double followingError() const noexcept { return m_command - m_x; }
    double acceleration() const noexcept { return m_a; }
    bool rampDone() const noexcept { return m_rampDone; }
    void setDrift(double countsPerS) noexcept { m_drift = countsPerS; }

private:
    void step(double h) noexcept;

    PlantParameters m_p;
    Control m_control = Control::Off;
    double m_x = 0.0;
    double m_v = 0.0;
    double m_a = 0.0;
    // Position control: command interpolated from m_from to m_to over m_period.
    double m_from = 0.0;
    double m_to = 0.0;
    double m_period = 0.0;
    double m_elapsed = 0.0;
    double m_command = 0.0;
    // Velocity control and ramps.
    double m_velocityTarget = 0.0;
    double m_velocityCommand = 0.0;
    double m_accel = 0.0;
    bool m_holdAfterRamp = true;
    bool m_rampDone = false;
    double m_drift = 0.0;
};

}  // namespace kerf::drivers::sim
