#include "motion/planner/share_ladder.h"

#include <algorithm>

#include "motion/planner/velocity_limits.h"

namespace kerf::motion {

size_t shareLadder(const MachineModel& model, const PathGeometry& geometry, double contourBudget,
                   double feed, std::array<ShareStage, 4>& stages) {
    const AxisBounds bounds = axisBounds(geometry);
    // The share the look-ahead takes for the whole curve (Lookahead::prepare): the first that
    // runs at the feed by the summed peaks, or the one giving the highest velocity.
    double chosen = kTangentialShares[0];
    double bestCap = -1.0;
    for (double share : kTangentialShares) {
        const Limits limits = tangentialLimits(model, bounds, share);
        const double cap = summedPeaksVelocityCap(model, geometry, bounds, limits, contourBudget);
        if (cap > bestCap * 1.05) {
            bestCap = cap;
            chosen = share;
        }
        if (cap >= 0.95 * feed) break;
    }
    size_t count = 0;
    double previous = 0.0;
    for (double share : kTangentialShares) {
        if (share <= chosen || count == stages.size()) break;
        const Limits limits = tangentialLimits(model, bounds, share);
        const double cap = elementVelocityCap(model, geometry, bounds, limits, contourBudget);
        if (cap <= previous) continue;
        // From `previous` to `cap` with a = 0 at both ends: (v0 + v1) / 2 (dv / A + A / J).
        const double length =
            (previous + cap) / 2.0 * ((cap - previous) / limits.accel + limits.accel / limits.jerk);
        stages[count++] = {length * 1.05, limits, cap};
        previous = cap;
    }
    return count;
}

}  // namespace kerf::motion
