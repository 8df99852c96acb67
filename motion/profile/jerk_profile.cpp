#include "motion/profile/jerk_profile.h"

#include <algorithm>
#include <cmath>

namespace kerf::motion {

namespace {

MotionState advance(MotionState x, double t, double jerk) noexcept {
    x.s += x.v * t + x.a * t * t / 2.0 + jerk * t * t * t / 6.0;
    x.v += x.a * t + jerk * t * t / 2.0;
    x.a += jerk * t;
    return x;
}

}  // namespace

void Profile::append(double duration, double jerk) noexcept {
    if (duration <= 0.0 || count >= static_cast<int>(phases.size())) return;
    phases[static_cast<size_t>(count)] = {duration, jerk};
    ++count;
}

double Profile::duration() const noexcept {
    double total = 0.0;
    for (int i = 0; i < count; ++i)
        total += phases[static_cast<size_t>(i)].duration;
    return total;
}

MotionState Profile::at(double t) const noexcept {
    MotionState x = start;
    for (int i = 0; i < count && t > 0.0; ++i) {
        const Phase& p = phases[static_cast<size_t>(i)];
        double step = std::min(t, p.duration);
        x = advance(x, step, p.jerk);
        t -= step;
        // The phases end with a = 0; clear the rounding so cruising does not drift.
        if (i == count - 1 && step == p.duration) x.a = 0.0;
    }
    if (t > 0.0) {
        x.s += x.v * t;
        x.a = 0.0;
    }
    return x;
}

MotionState Profile::end() const noexcept {
    return at(duration());
}

Profile Profile::then(double t, const Profile& next) const noexcept {
    Profile out;
    out.start = start;
    double left = t;
    for (int i = 0; i < count && left > 0.0; ++i) {
        const Phase& p = phases[static_cast<size_t>(i)];
        double step = std::min(left, p.duration);
        out.append(step, p.jerk);
        left -= step;
    }
    if (left > 0.0) out.append(left, 0.0);  // cruising
    for (int i = 0; i < next.count; ++i) {
        out.append(next.phases[static_cast<size_t>(i)].duration,
                   next.phases[static_cast<size_t>(i)].jerk);
    }
    return out;
}

double velocityAfterRampDown(const MotionState& state, double jerk) noexcept {
    return state.v + state.a * std::fabs(state.a) / (2.0 * jerk);
}

Profile velocityChange(const MotionState& state, double target, const Limits& limits) noexcept {
    Profile profile;
    profile.start = state;
    const double jerk = limits.jerk;
    const double accel = limits.accel;
    if (jerk <= 0.0 || accel <= 0.0) return profile;
    // Work in the direction of the change: sigma = +1 accelerates.
    double sigma = target >= velocityAfterRampDown(state, jerk) ? 1.0 : -1.0;
    double a0 = sigma * state.a;
    double dv = sigma * (target - state.v);
    double peakSq = (2.0 * jerk * dv + a0 * a0) / 2.0;
    double peak = std::sqrt(std::max(0.0, peakSq));
    if (peak <= accel) {
        profile.append((peak - a0) / jerk, sigma * jerk);
        profile.append(peak / jerk, -sigma * jerk);
    } else {
        double dvUp = (accel * accel - a0 * a0) / (2.0 * jerk);
        double dvDown = accel * accel / (2.0 * jerk);
        profile.append((accel - a0) / jerk, sigma * jerk);
        profile.append((dv - dvUp - dvDown) / accel, 0.0);
        profile.append(accel / jerk, -sigma * jerk);
    }
    return profile;
}

Profile meetProfile(const MotionState& state, double limit, const Limits& limits) noexcept {
    double rampDown = velocityAfterRampDown(state, limits.jerk);
    return velocityChange(state, std::min(limit, rampDown), limits);
}

double distanceToMeet(const MotionState& state, double limit, const Limits& limits) noexcept {
    return meetProfile(state, limit, limits).end().s - state.s;
}

}  // namespace kerf::motion
