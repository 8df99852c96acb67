#pragma once

#include <vector>

#include "core/geometry/axes.h"

namespace kerf {

// A circular arc in space of less than half a turn from `from` to `to` about `centre` (both at the
// same distance from it), in the plane of the three points: the points after `from` (the last
// exactly `to`) whose chords stay within `tolerance` of the arc, equally spaced along it.
std::vector<Vec3> arcChordPoints(const Vec3& from, const Vec3& to, const Vec3& centre,
                                 double tolerance);

}  // namespace kerf
