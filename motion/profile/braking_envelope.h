#pragma once

#include "motion/profile/jerk_profile.h"

// Closed forms the look-ahead uses to decide which velocity limits ahead bind the motion.
// Pure functions: any thread.
namespace kerf::motion {

// Highest velocity at distance `distance` before a point that must be reached with
// (velocity <= anchorVelocity, a = 0), over all time-optimal braking motions that meet it: the
// final jerk ramp followed backwards by the constant-deceleration parabola.
double brakingEnvelope(double distance, double anchorVelocity, const Limits& limits) noexcept;

// Highest velocity with a = 0 from which (anchorVelocity, a = 0) is met within `distance`.
double maxRestingVelocity(double distance, double anchorVelocity, const Limits& limits) noexcept;

// The real root of x^3 + p x + q = 0 for p >= 0 (there is exactly one).
double realCubicRoot(double p, double q) noexcept;

// Distance to brake from (velocity, a = 0) to (0, a = 0): the look-ahead window's length.
double stoppingDistance(double velocity, const Limits& limits) noexcept;

}  // namespace kerf::motion
