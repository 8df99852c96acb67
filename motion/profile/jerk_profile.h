#pragma once

#include <array>

// One-dimensional jerk-limited motion along the path parameter s: the building block of the
// servo cycle's path generator, of jog and homing moves, and of the planner's look-ahead.
// Every function is noexcept, allocation-free and O(1): callable from any thread, including RT.
namespace kerf::motion {

struct MotionState {
    double s = 0.0;  // position (mm or deg)
    double v = 0.0;  // velocity per second
    double a = 0.0;  // acceleration per second^2
};

struct Limits {
    double accel = 0.0;  // > 0
    double jerk = 0.0;   // > 0
};

// Up to three phases of constant jerk followed by cruising at the final velocity (a = 0).
struct Profile {
    struct Phase {
        double duration = 0.0;
        double jerk = 0.0;
    };
    MotionState start;
    std::array<Phase, 8> phases{};
    int count = 0;

    double duration() const noexcept;
    // State after time t; past the last phase the profile cruises with a = 0.
    MotionState at(double t) const noexcept;
    // State at the end of the phases.
    MotionState end() const noexcept;
    void append(double duration, double jerk) noexcept;
    // The first `t` seconds of this profile followed by `next` (which starts where they end).
    Profile then(double t, const Profile& next) const noexcept;
};

// Velocity reached if the acceleration is brought to zero at once (with full jerk).
double velocityAfterRampDown(const MotionState& state, double jerk) noexcept;

// Time-optimal change from `state` to velocity `target` with a = 0 at the end, |a| <= accel,
// |j| <= jerk. Assumes |state.a| <= accel.
Profile velocityChange(const MotionState& state, double target, const Limits& limits) noexcept;

// Distance needed to arrive with a = 0 at a velocity no higher than `limit`: bring the
// acceleration to zero if that already ends at or below `limit`, else change to `limit`.
double distanceToMeet(const MotionState& state, double limit, const Limits& limits) noexcept;

// The profile that meets (limit, a = 0) in the least distance (see distanceToMeet).
Profile meetProfile(const MotionState& state, double limit, const Limits& limits) noexcept;

}  // namespace kerf::motion
