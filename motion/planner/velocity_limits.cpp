#include "motion/planner/velocity_limits.h"

#include <algorithm>
#include <array>
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

Limits topTangentialLimits(const MachineModel& model, const AxisBounds& bounds) {
    const Limits whole = tangentialLimits(model, bounds, 1.0);
    return {whole.accel * kTopAccelShare, whole.jerk * kTangentialShares[0]};
}

namespace {

constexpr double kQuarterTurn = 1.5707963267948966192;

// Along a circle or helix, axis i moves as rate_i s + amp_i cos(theta), theta = phi - psi_i: its
// tangent, curvature and curvature rate are the sine and cosine of one angle, scaled by
// c1 = amp k, c2 = amp k^2, c3 = amp k^3. So a_i = rate_i a + c1 a sin + c2 v^2 cos and
// j_i = rate_i j + (c1 j - c3 v^3) sin + 3 c2 v a cos (up to signs): the circle's share peaks at
// sqrt(x^2 + y^2), not x + y, which is what a line's bounds would add up to; and only where the
// element's sweep reaches that angle (a short arc of a fitted curve stays near one angle).
struct AxisTerms {
    double linear = 0.0;  // |rate_i| (all of |u_i| on a line)
    double c1 = 0.0;
    double c2 = 0.0;
    double c3 = 0.0;
    // The sweep folded into [0, pi/2] (|sin| and |cos| of theta), one interval per quarter turn.
    std::array<std::array<double, 2>, 6> folded{};
    size_t pieces = 0;
};

AxisTerms axisTerms(const PathGeometry& geometry, const AxisBounds& bounds, size_t i) {
    AxisTerms terms;
    if (!geometry.curved() || i >= 3) {
        terms.linear = bounds.tangent[i];
        return terms;
    }
    double amp = std::hypot(geometry.e1[i], geometry.e2[i]) * geometry.radius;
    terms.linear = std::fabs(geometry.rate[i]);
    terms.c1 = amp * geometry.k;
    terms.c2 = terms.c1 * geometry.k;
    terms.c3 = terms.c2 * geometry.k;
    const double psi = std::atan2(geometry.e2[i], geometry.e1[i]);
    const double from = geometry.phi0 - psi;
    const double sweep = std::min(geometry.k * geometry.length, 4.0 * kQuarterTurn);
    // |sin| and |cos| repeat every quarter turn, mirrored in every other one.
    const double to = from + sweep;
    for (auto quarter = static_cast<long>(std::floor(from / kQuarterTurn));
         terms.pieces < terms.folded.size(); ++quarter) {
        const double start = static_cast<double>(quarter) * kQuarterTurn;
        const double a = std::max(from, start) - start;
        const double b = std::min(to, start + kQuarterTurn) - start;
        if (b >= a) {
            const bool mirrored = quarter % 2 != 0;
            const double lo = std::clamp(mirrored ? kQuarterTurn - b : a, 0.0, kQuarterTurn);
            const double hi = std::clamp(mirrored ? kQuarterTurn - a : b, 0.0, kQuarterTurn);
            terms.folded[terms.pieces++] = {lo, hi};
        }
        if (start + kQuarterTurn >= to) break;
    }
    return terms;
}

// Highest v^2 with linear A_t + c1 A_t |sin| + c2 v^2 |cos| <= A over the sweep. On [0, pi/2]
// (room - p sin) / (q cos) falls until sin = p / room and rises after: its least value on an
// interval is at that angle clamped into it.
double accelCapSquared(const AxisTerms& t, const Limits& limits, double accel) {
    const double room = accel - t.linear * limits.accel;
    const double p = t.c1 * limits.accel;
    const double turning = room > p ? std::asin(p / room) : kQuarterTurn;
    double least = kNone;
    for (size_t k = 0; k < t.pieces; ++k) {
        const double angle = std::clamp(turning, t.folded[k][0], t.folded[k][1]);
        const double numerator = room - p * std::sin(angle);
        if (numerator < 0.0 || room - p * std::sin(t.folded[k][1]) < 0.0) return 0.0;
        const double denominator = t.c2 * std::cos(angle);
        if (denominator > 0.0) least = std::min(least, numerator / denominator);
    }
    return least;
}

// Largest (c1 J_t + c3 v^3) |sin| + 3 c2 A_t v |cos| over the sweep: R cos(angle - peak) on
// [0, pi/2], largest at the peak clamped into each interval.
double sweepJerk(const AxisTerms& t, const Limits& limits, double v) {
    const double a = t.c1 * limits.jerk + t.c3 * v * v * v;
    const double b = 3.0 * t.c2 * limits.accel * v;
    const double peak = std::atan2(a, b);
    double largest = 0.0;
    for (size_t k = 0; k < t.pieces; ++k) {
        const double angle = std::clamp(peak, t.folded[k][0], t.folded[k][1]);
        largest = std::max(largest, a * std::sin(angle) + b * std::cos(angle));
    }
    return largest;
}

// Highest v with linear J_t + (the sweep's jerk) <= J.
double jerkCap(const AxisTerms& t, const Limits& limits, double jerk, double upperBound) {
    double room = jerk - t.linear * limits.jerk;
    auto fits = [&](double v) { return sweepJerk(t, limits, v) <= room; };
    if (room <= 0.0 || !fits(0.0)) return 0.0;
    if (fits(upperBound)) return upperBound;
    // The left side rises with v: bisection.
    double lo = 0.0;
    double hi = upperBound;
    for (int k = 0; k < 60 && hi - lo > 1e-9 * hi; ++k) {
        double mid = 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace

double elementVelocityCap(const MachineModel& model, const PathGeometry& geometry,
                          const AxisBounds& bounds, const Limits& limits, double contourBudget) {
    double cap = kNone;
    for (size_t i = 0; i < model.axes.size(); ++i) {
        const AxisModel& axis = model.axes[i];
        double u = bounds.tangent[i];
        double n = bounds.curvature[i];
        if (u < 1e-12 && n < 1e-12) continue;
        if (!axis.enabled) return 0.0;
        if (u > 0.0) cap = std::min(cap, axis.velocity / u);
        AxisTerms t = axisTerms(geometry, bounds, i);
        if (t.linear * limits.accel > axis.accel) return 0.0;
        if (t.c2 > 0.0) cap = std::min(cap, std::sqrt(accelCapSquared(t, limits, axis.accel)));
        cap = jerkCap(t, limits, axis.jerk, cap);
    }
    double kappa = geometry.curvature();
    if (kappa > 0.0) {
        double t = model.filterTimeS();
        cap = std::min(cap, std::sqrt(24.0 * std::max(0.0, contourBudget) / (kappa * t * t)));
    }
    return std::max(0.0, cap);
}

double summedPeaksVelocityCap(const MachineModel& model, const PathGeometry& geometry,
                              const AxisBounds& bounds, const Limits& limits,
                              double contourBudget) {
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

bool curvatureStepFits(const MachineModel& model, const AxisVector& stepSum,
                       const PointJerkTerms& before, const PointJerkTerms& after, double v) {
    const double t = model.filterTimeS();
    for (size_t i = 0; i < model.axes.size(); ++i) {
        if (stepSum[i] <= 0.0) continue;
        for (const PointJerkTerms* side : {&before, &after}) {
            double jerk = ((side->curvatureRate[i] * v + stepSum[i] / t) * v +
                           3.0 * side->curvature[i] * side->limits.accel) *
                              v +
                          side->tangent[i] * side->limits.jerk;
            if (jerk > model.axes[i].jerk) return false;
        }
    }
    return true;
}

double curvatureStepCap(const MachineModel& model, const AxisVector& stepSum,
                        const PointJerkTerms& before, const PointJerkTerms& after,
                        double upperBound) {
    // Per axis and side: n' v^3 + (step / T) v^2 + 3 |n| A_t v + |u| J_t <= J. Every coefficient
    // is >= 0, so the left side rises and is convex for v >= 0: Newton from above converges
    // monotonically to the one root.
    const double t = model.filterTimeS();
    double cap = upperBound;
    for (size_t i = 0; i < model.axes.size(); ++i) {
        if (stepSum[i] <= 0.0) continue;
        for (const PointJerkTerms* side : {&before, &after}) {
            double room = model.axes[i].jerk - side->tangent[i] * side->limits.jerk;
            if (room <= 0.0) return 0.0;
            double cubic = side->curvatureRate[i];
            double square = stepSum[i] / t;
            double linear = 3.0 * side->curvature[i] * side->limits.accel;
            auto excess = [&](double v) { return ((cubic * v + square) * v + linear) * v - room; };
            if (excess(cap) <= 0.0) continue;
            // Each term alone reaching the room bounds the root from above.
            double v = std::min(cap, std::sqrt(room / square));
            if (linear > 0.0) v = std::min(v, room / linear);
            if (cubic * v * v * v > room) v = std::cbrt(room / cubic);
            for (int k = 0; k < 100; ++k) {
                double slope = (3.0 * cubic * v + 2.0 * square) * v + linear;
                double next = v - excess(v) / slope;
                if (!(next < v)) break;
                v = next;
            }
            cap = std::min(cap, std::max(0.0, v));
        }
    }
    return cap;
}

}  // namespace kerf::motion
