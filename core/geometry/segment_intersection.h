#pragma once

#include <vector>

#include "core/geometry/offset_contour.h"

namespace kerf {

// Intersections of the carriers (infinite line, full circle) of two segments: none, one or two
// points; parallel lines and concentric circles have none.
std::vector<Vec2> carrierIntersections(const PlanarSegment& a, const PlanarSegment& b);

}  // namespace kerf
