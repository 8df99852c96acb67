#include "motion/profile/braking_envelope.h"

#include <cmath>

namespace kerf::motion {

double realCubicRoot(double p, double q) noexcept {
    double disc = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
    return std::cbrt(-q / 2.0 + disc) + std::cbrt(-q / 2.0 - disc);
}

double brakingEnvelope(double distance, double anchorVelocity, const Limits& limits) noexcept {
    if (distance <= 0.0) return anchorVelocity;
    const double j = limits.jerk;
    const double a = limits.accel;
    double rampTime = a / j;
    double rampDistance = anchorVelocity * rampTime + j * rampTime * rampTime * rampTime / 6.0;
    if (distance <= rampDistance) {
        // Backwards from the anchor: d = v tau + j tau^3 / 6, v = v_anchor + j tau^2 / 2.
        double tau = realCubicRoot(6.0 * anchorVelocity / j, -6.0 * distance / j);
        return anchorVelocity + j * tau * tau / 2.0;
    }
    double rampVelocity = anchorVelocity + a * a / (2.0 * j);
    return std::sqrt(rampVelocity * rampVelocity + 2.0 * a * (distance - rampDistance));
}

double maxRestingVelocity(double distance, double anchorVelocity, const Limits& limits) noexcept {
    if (distance <= 0.0) return anchorVelocity;
    const double j = limits.jerk;
    const double a = limits.accel;
    // From rest-acceleration the change dv takes t(dv) = 2 sqrt(dv / j) without a constant
    // phase, dv / a + a / j with one, and covers (2 v_anchor + dv) / 2 * t(dv).
    double dvFull = a * a / j;
    double distanceFull = (2.0 * anchorVelocity + dvFull) * a / j;
    double dv = 0.0;
    if (distance <= distanceFull) {
        double x = realCubicRoot(2.0 * anchorVelocity, -distance * std::sqrt(j));
        dv = x * x;
    } else {
        // dv^2 / a + dv (a / j + 2 v / a) + 2 v a / j - 2 d = 0
        double qa = 1.0 / a;
        double qb = a / j + 2.0 * anchorVelocity / a;
        double qc = 2.0 * anchorVelocity * a / j - 2.0 * distance;
        dv = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
    }
    return anchorVelocity + dv;
}

double stoppingDistance(double velocity, const Limits& limits) noexcept {
    return distanceToMeet({0.0, velocity, 0.0}, 0.0, limits);
}

}  // namespace kerf::motion
