#include "motion/planner/soft_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::motion {

namespace {

// Range of one axis over the element: the linear part is monotonic, the circle part is
// amp cos(phi - psi).
void axisRange(const PathGeometry& g, size_t axis, double& lo, double& hi) {
    double a = g.origin[axis];
    double b = g.origin[axis] + g.rate[axis] * g.length;
    // std::min/max would drop a NaN depending on the order: keep it, the checks refuse it.
    if (std::isnan(a) || std::isnan(b)) {
        lo = hi = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    lo = std::min(a, b);
    hi = std::max(a, b);
    if (!g.curved() || axis >= 3) return;
    double amp = std::hypot(g.e1[axis], g.e2[axis]) * g.radius;
    CosRange c = cosRange(g.phi0, g.phi0 + g.k * g.length, std::atan2(g.e2[axis], g.e1[axis]));
    lo += amp * c.lo;
    hi += amp * c.hi;
}

}  // namespace

std::optional<SoftLimitViolation> checkSoftLimits(const MachineModel& model,
                                                  const PathGeometry& geometry, double toolLength) {
    for (size_t i = 0; i < model.axes.size(); ++i) {
        const AxisModel& axis = model.axes[i];
        double lo = 0.0;
        double hi = 0.0;
        axisRange(geometry, i, lo, hi);
        int index = static_cast<int>(i);
        if (!axis.enabled) {
            if (!(hi - lo <= 1e-9)) {
                return SoftLimitViolation{index, hi, 0.0, true};
            }
            continue;
        }
        double jointLo = jointFromAxis(model, index, lo, toolLength);
        double jointHi = jointFromAxis(model, index, hi, toolLength);
        // Rounding of programmed values must not refuse a move that ends on the limit.
        constexpr double kSlack = 1e-9;
        // Each test is written to hold only for a number inside the limits: NaN (0 * inf in the
        // range, NaN in the element) fails every comparison and so violates.
        if (!(jointHi <= axis.maxLimit + kSlack)) {
            return SoftLimitViolation{index, jointHi, axis.maxLimit, false};
        }
        if (!(jointLo >= axis.minLimit - kSlack)) {
            return SoftLimitViolation{index, jointLo, axis.minLimit, false};
        }
    }
    return std::nullopt;
}

}  // namespace kerf::motion
