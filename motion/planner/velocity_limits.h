#pragma once

#include "motion/kinematics/machine_model.h"
#include "motion/path/path_geometry.h"
#include "motion/profile/jerk_profile.h"

// Velocity limits of one path element from the machine's per-axis limits, for the servo
// cycle's axis smoothing filter (a moving average of length T). Planner thread.
//
// Along the element, axis i moves with v_i = u_i v, a_i = u_i a + n_i v^2 and
// j_i = u_i j + 3 n_i v a + n'_i v^3 (u = dp/ds, n = d2p/ds2, n' = d3p/ds3; a, j tangential).
// The filter keeps every bound of its input and turns a step of a_i (a curvature step at an
// element boundary) into a ramp of slope step / T; it shrinks a curve of curvature kappa by
// kappa v^2 T^2 / 24.
namespace kerf::motion {

// Tangential limits are a share of the axes' limits; the rest is left to the curvature terms.
// A few fixed shares, from 90 % on straight paths down to 2 % on tight curves, so that long runs
// of elements share their limits (the servo cycle must arrive with a = 0 where they change).
inline constexpr double kTangentialShares[] = {0.9, 0.6, 0.3, 0.1, 0.02};

Limits tangentialLimits(const MachineModel& model, const AxisBounds& bounds, double share);

// Above the shares, for an element whose velocity limit the top share does not lower (a line, a
// gently curved span): 98 % of the acceleration with the jerk of the highest share, whose
// remaining 10 % the curvature steps at the element's ends need (raising both to 95 % made the
// FIGURES rows at J = 50000 4 % slower; 100 % of the acceleration left some spans of a fitted row
// below it and added points with a = 0 between them).
inline constexpr double kTopAccelShare = 0.98;

Limits topTangentialLimits(const MachineModel& model, const AxisBounds& bounds);

// Highest velocity on the element for velocity, acceleration, continuous jerk and filter
// contour error (`contourBudget` mm), given tangential limits.
double elementVelocityCap(const MachineModel& model, const PathGeometry& geometry,
                          const AxisBounds& bounds, const Limits& limits, double contourBudget);

// The same limit with each axis's peaks added as if they coincided (no better than
// elementVelocityCap; the bound before arcs were phase-aware). The look-ahead still picks the
// tangential share by it: picking by the exact limit chose low shares on short arcs that cannot
// reach their cap anyway, 0.5-1.3 % slower on the 0.2 mm FIGURES rows at J = 50000.
double summedPeaksVelocityCap(const MachineModel& model, const PathGeometry& geometry,
                              const AxisBounds& bounds, const Limits& limits, double contourBudget);

// What the pre-filter jerk of each axis is made of at one point of the path, on one side of an
// element boundary: |u_i|, |n_i|, |n'_i| there and the tangential limits of that element.
struct PointJerkTerms {
    AxisVector tangent{};
    AxisVector curvature{};
    AxisVector curvatureRate{};
    Limits limits;
};

PointJerkTerms jerkTermsAt(const PathGeometry& geometry, double s, const Limits& limits);

// Highest velocity at a curvature step (an element boundary where n jumps): the filter turns
// the steps within one filter length, summing to stepSum_i, into jerk stepSum_i v^2 / T, which
// must fit next to the continuous jerk |u_i| J_t + 3 |n_i| A_t v + |n'_i| v^3 on either side.
double curvatureStepCap(const MachineModel& model, const AxisVector& stepSum,
                        const PointJerkTerms& before, const PointJerkTerms& after,
                        double upperBound);

// Whether velocity v fits that inequality: curvatureStepCap(...) >= v, without the root.
bool curvatureStepFits(const MachineModel& model, const AxisVector& stepSum,
                       const PointJerkTerms& before, const PointJerkTerms& after, double v);

}  // namespace kerf::motion
