#pragma once

#include "motion/kinematics/machine_model.h"
#include "motion/rt/path_generator.h"

// The spindle as the servo cycle drives it: speed control with jerk-limited ramps (override,
// constant surface speed), oriented stops, and a lock to the path for synchronised moves (the
// angle then follows the path parameter). The angle is a continuous position in degrees.
// RT thread, O(1), noexcept.
namespace kerf::motion {

class SpindleChannel {
public:
    void configure(const MachineModel& model) noexcept;
    void reset(double angleDeg) noexcept;

    // direction: 1 cw (positive angle), -1 ccw, 0 stop.
    void command(int direction, double rpm, double surfaceSpeedMPerMin, double maxRpm) noexcept;
    void setOverride(double factor) noexcept { m_override = factor; }
    // Stop at `angleDeg` (modulo 360) and hold there.
    void orient(double angleDeg) noexcept;
    void lock() noexcept {
        m_mode = Mode::Locked;
        m_gen.reset(m_angle);
    }
    void unlock() noexcept;
    void setLockedAngle(double angleDeg, double velocityDegPerS) noexcept;

    // One period; `radiusMm` is the tool's X radius for constant surface speed.
    void update(double dt, double radiusMm) noexcept;

    double angle() const noexcept { return m_angle; }
    double rpm() const noexcept { return m_velocity / 6.0; }
    double commandedRpm() const noexcept { return m_rpm; }
    bool settled() const noexcept;  // at speed, oriented or locked

private:
    enum class Mode : uint8_t { Speed, Orient, Locked };

    Mode m_mode = Mode::Speed;
    Limits m_limits;  // deg/s^2, deg/s^3
    double m_maxRpm = 0.0;
    int m_direction = 0;
    double m_rpm = 0.0;
    double m_surfaceSpeed = 0.0;
    double m_cssMaxRpm = 0.0;
    double m_override = 1.0;
    double m_angle = 0.0;
    double m_velocity = 0.0;  // deg/s
    double m_targetVelocity = 0.0;
    // A new speed command counts from the next update(), which turns it into the target: until
    // then the spindle is not at the commanded speed, whatever the old target.
    bool m_commandApplied = true;
    double m_orientTarget = 0.0;
    double m_orientGoal = 0.0;
    bool m_orientPlaced = false;
    PathGenerator m_gen;
};

}  // namespace kerf::motion
