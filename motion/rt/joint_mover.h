#pragma once

#include "motion/rt/path_generator.h"

// Manual motion of one axis: continuous jog, incremental jog and handwheel, each jerk-limited
// and stopping at the soft limits. Works on the axis' tool-tip coordinate. RT thread, O(1).
namespace kerf::motion {

class JointMover {
public:
    // Continuous jog at `velocity` (signed) until stop() or the limit in that direction.
    void jog(int axis, double position, double velocity, double lo, double hi) noexcept;
    // Move to `target` (increment, handwheel); moveTarget() shifts it while moving.
    void moveTo(int axis, double position, double target, double velocity) noexcept;
    void moveTarget(double target) noexcept { m_target = target; }
    void stop() noexcept { m_stopping = true; }

    // One period: the new position of the axis; false once it has come to rest.
    bool update(double dt, const Limits& limits, double& position) noexcept;

    bool active() const noexcept { return m_active; }
    int axis() const noexcept { return m_axis; }
    double target() const noexcept { return m_target; }

private:
    PathGenerator m_gen;  // along m_direction from m_origin
    int m_axis = -1;
    bool m_active = false;
    bool m_continuous = false;
    bool m_stopping = false;
    double m_origin = 0.0;
    double m_direction = 1.0;
    double m_velocity = 0.0;
    double m_target = 0.0;
};

}  // namespace kerf::motion
