#pragma once

#include <array>

#include "motion/path/path_geometry.h"

// Biarcs: two circular arcs, tangent to each other, from a point and unit tangent to another
// point and unit tangent (XYZ). Planner thread.
namespace kerf::motion {

// The biarc with equal tangent legs: the joint tangent is parallel to the line between the two
// leg ends. The other axes stay at `base`. Returns the number of arcs (2), or 0 when the
// tangents point away from each other so that no such biarc exists.
int makeBiarc(const AxisVector& base, const Vec3Array& p0, const Vec3Array& t0, const Vec3Array& p1,
              const Vec3Array& t1, std::array<PathGeometry, 2>& arcs);

}  // namespace kerf::motion
