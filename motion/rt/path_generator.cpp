#include "motion/rt/path_generator.h"

#include <cmath>

namespace kerf::motion {

namespace {

constexpr double kSlack = 1e-10;

}  // namespace

bool canMeet(const MotionState& state, const Constraint& c, const Limits& limits) noexcept {
    return distanceToMeet(state, c.velocity, limits) <= c.s - state.s + kSlack;
}

bool PathGenerator::atRest() const noexcept {
    return std::fabs(m_state.v) < 1e-9 && std::fabs(m_state.a) < 1e-6;
}

Profile PathGenerator::plan(double dt, double targetVelocity, const Limits& limits,
                            std::span<const Constraint> constraints) const noexcept {
    Profile track = velocityChange(m_state, targetVelocity, limits);
    auto meetsAll = [&](const MotionState& x) {
        for (const Constraint& c : constraints) {
            if (!canMeet(x, c, limits)) return false;
        }
        return true;
    };
    if (meetsAll(track.at(dt))) return track;
    // For every constraint the tracking would break: track until the last moment it can still
    // be met, then meet it. Braking for one constraint may break another (the least distance to
    // reach a velocity is not monotonic in that velocity), so take the candidate that keeps all
    // of them, tracking longest; failing that, the one that slows down most.
    Profile best = track;
    double bestSwitch = -1.0;
    double slowest = 1e300;
    Profile fallback = track;
    for (const Constraint& c : constraints) {
        if (canMeet(track.at(dt), c, limits)) continue;
        double lo = 0.0;
        double hi = dt;
        if (!canMeet(m_state, c, limits)) {
            hi = 0.0;
        } else {
            for (int i = 0; i < 48; ++i) {
                double mid = (lo + hi) / 2.0;
                if (canMeet(track.at(mid), c, limits))
                    lo = mid;
                else
                    hi = mid;
            }
        }
        Profile candidate = track.then(lo, meetProfile(track.at(lo), c.velocity, limits));
        MotionState end = candidate.at(dt);
        if (meetsAll(end) && lo > bestSwitch) {
            best = candidate;
            bestSwitch = lo;
        }
        if (end.v < slowest) {
            slowest = end.v;
            fallback = candidate;
        }
    }
    return bestSwitch >= 0.0 ? best : fallback;
}

void PathGenerator::step(double dt, double targetVelocity, const Limits& limits,
                         std::span<const Constraint> constraints) noexcept {
    m_state = plan(dt, targetVelocity, limits, constraints).at(dt);
    if (m_state.v < 0.0 && m_state.v > -1e-9) m_state.v = 0.0;
}

}  // namespace kerf::motion
