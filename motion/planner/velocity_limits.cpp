#include "motion/planner/velocity_limits.h"

#include <algorithm>
#include <cmath>

#include "motion/profile/braking_envelope.h"

namespace kerf::motion {

namespace {

constexpr double kNone = 1e300;

}  // namespace

Limits tangentialLimits(const MachineModel& model, const AxisBounds& bounds, double share) {
    // Linear axes share the path's mm; a rotary axis contributes in path units per degree.
    double accel = kNone;
    double jerk = kNone;
    for (size_t i = 0; i < model.axes.size(); ++i) {
        const AxisModel& axis = model.axes[i];
        double u = bounds.tangent[i];
        if (!axis.enabled || u < 1e-12) continue;
        double scale = axis.rotary ? u : 1.0;
        accel = std::min(accel, axis.accel / scale);
        jerk = std::min(jerk, axis.jerk / scale);
    }
    if (accel == kNone) return {1.0, 1.0};
    return {accel * share, jerk * share};
}

double elementVelocityCap(const MachineModel& model, const PathGeometry& geometry,
                          const AxisBounds& bounds, const Limits& limits, double contourBudget) {
    double cap = kNone;
    for (size_t i = 0; i < model.axes.size(); ++i) {
        const AxisModel& axis = model.axes[i];
        double u = bounds.tangent[i];
        double n = bounds.curvature[i];
        double dn = bounds.curvatureRate[i];
        if (u < 1e-12 && n < 1e-12) continue;
        if (!axis.enabled) return 0.0;
        if (u > 0.0) cap = std::min(cap, axis.velocity / u);
        if (n > 0.0) {
            double room = axis.accel - u * limits.accel;
            cap = std::min(cap, room > 0.0 ? std::sqrt(room / n) : 0.0);
        }
        // |u| J_t + 3 |n| A_t v + |n'| v^3 <= J
        double jerkRoom = axis.jerk - u * limits.jerk;
        if (jerkRoom <= 0.0) {
            cap = 0.0;
        } else if (dn > 0.0) {
            cap = std::min(cap, realCubicRoot(3.0 * n * limits.accel / dn, -jerkRoom / dn));
        } else if (n > 0.0) {
            cap = std::min(cap, jerkRoom / (3.0 * n * limits.accel));
        }
    }
    double kappa = geometry.curvature();
    if (kappa > 0.0) {
        double t = model.filterTimeS();
        cap = std::min(cap, std::sqrt(24.0 * std::max(0.0, contourBudget) / (kappa * t * t)));
    }
    return std::max(0.0, cap);
}

PointJerkTerms jerkTermsAt(const PathGeometry& geometry, double s, const Limits& limits) {
    PointJerkTerms terms;
    terms.limits = limits;
    PathPoint p = pointAt(geometry, s);
    for (size_t i = 0; i < terms.tangent.size(); ++i) {
        terms.tangent[i] = std::fabs(p.tangent[i]);
        terms.curvature[i] = std::fabs(p.curvature[i]);
        // n' = k x n on the circle part: |n'_i| = k |tangential circle component| * r k^2 / (r k)
        terms.curvatureRate[i] =
            geometry.curved() && i < 3
                ? std::fabs(p.tangent[i] - geometry.rate[i]) * geometry.k * geometry.k
                : 0.0;
    }
    return terms;
}

double curvatureStepCap(const MachineModel& model, const AxisVector& stepSum,
                        const PointJerkTerms& before, const PointJerkTerms& after,
                        double upperBound) {
    const double t = model.filterTimeS();
    auto fits = [&](double v) {
        for (size_t i = 0; i < model.axes.size(); ++i) {
            if (stepSum[i] <= 0.0) continue;
            double continuous = 0.0;
            for (const PointJerkTerms* side : {&before, &after}) {
                continuous =
                    std::max(continuous, side->tangent[i] * side->limits.jerk +
                                             3.0 * side->curvature[i] * side->limits.accel * v +
                                             side->curvatureRate[i] * v * v * v);
            }
            if (stepSum[i] * v * v / t + continuous > model.axes[i].jerk) return false;
        }
        return true;
    };
    if (fits(upperBound)) return upperBound;
    double lo = 0.0;
    double hi = upperBound;
    for (int k = 0; k < 40; ++k) {
        double mid = (lo + hi) / 2.0;
        if (fits(mid))
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

}  // namespace kerf::motion
