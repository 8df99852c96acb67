#pragma once

#include <span>

#include "motion/profile/jerk_profile.h"

// The servo cycle's interpolator along one coordinate (the path parameter, or a joint when
// jogging): each period it moves towards a target velocity with jerk-limited changes while every
// constraint ahead stays reachable, and when continuing would break one it brakes so that it
// meets that constraint exactly (the switch point inside the period is found by bisection).
// O(constraints) per call, noexcept, no allocation: RT thread.
namespace kerf::motion {

// Reach position `s` with a = 0 and a velocity no higher than `velocity` (the tangential limits
// may change there). Constraints behind the current position must not be passed in.
struct Constraint {
    double s = 0.0;
    double velocity = 0.0;
};

class PathGenerator {
public:
    void reset(double s) noexcept { m_state = {s, 0.0, 0.0}; }
    const MotionState& state() const noexcept { return m_state; }
    void setState(const MotionState& state) noexcept { m_state = state; }
    bool atRest() const noexcept;

    // The motion for the next `dt`: towards the target velocity while every constraint stays
    // reachable, braking for the first one that would not. Does not change the state.
    Profile plan(double dt, double targetVelocity, const Limits& limits,
                 std::span<const Constraint> constraints) const noexcept;
    void step(double dt, double targetVelocity, const Limits& limits,
              std::span<const Constraint> constraints) noexcept;

private:
    MotionState m_state;
};

// True when `state` can still meet `c` (distanceToMeet fits before c.s).
bool canMeet(const MotionState& state, const Constraint& c, const Limits& limits) noexcept;

}  // namespace kerf::motion
