#pragma once

#include <array>
#include <cstddef>

#include "motion/kinematics/machine_model.h"
#include "motion/path/path_geometry.h"
#include "motion/profile/jerk_profile.h"

// The tangential share of the axis limits along a curve that starts or ends at rest: at low
// velocity the centripetal part needs little of each axis's acceleration, so the tangential
// part may have more. A curve that cannot run at its feed with 90 % of the limits for the
// tangential acceleration (R5 at F6000 on the built-in mill: 66 mm/s) gets, from rest, a stage at
// 90 % up to that velocity, then one at 60 % up to its cap, and so on down to the share that
// lets it run at its feed, instead of that lowest share (10 %: 200 mm/s^2) all the way.
// Planner thread.
namespace kerf::motion {

struct ShareStage {
    double length = 0.0;  // path length the stage needs to reach its cap from the one before
    Limits limits;        // tangential limits of the stage
    double cap = 0.0;     // highest velocity on the curve with those limits
};

// Stages from rest along `geometry` (a curve, constant curvature) up to the share the look-ahead
// takes for the whole curve (the largest that lets it run at `feed` mm/s); none when 90 % does.
size_t shareLadder(const MachineModel& model, const PathGeometry& geometry, double contourBudget,
                   double feed, std::array<ShareStage, 4>& stages);

}  // namespace kerf::motion
