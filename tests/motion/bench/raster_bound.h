#pragma once

#include "tests/motion/raster_program.h"

// Lower bounds for the time of the gen_nc raster (shared/anchors/FIGURES.md "bound"): each row
// (its true 3D length) with trapezoidal acceleration at `accel` between the U-turn speed, every
// U-turn arc at its centripetal limit sqrt(accel R) (both capped by the feed), at rest at the
// start and at the end. With `jerk` > 0 the jerk-aware variant: rows as jerk-limited (S-curve)
// profiles and U-turns also at most (jerk R^2)^(1/3), where an axis's jerk on the circle,
// v^3 / R^2, reaches the limit.
namespace kerf::motion::test {

double rasterBoundS(const RasterOptions& options, double accel, double jerk = 0.0);

}  // namespace kerf::motion::test
