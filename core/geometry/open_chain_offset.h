#pragma once

#include <optional>
#include <vector>

#include "core/geometry/arc_math.h"
#include "core/geometry/offset_contour.h"

namespace kerf {

// Offsets an open chain (each segment starts where the previous one ends) by `distance`,
// positive to the left of the direction of travel: the points at exactly that distance from the
// chain on that side, in order. Lines stay lines and arcs stay arcs about the same centre; convex
// corners get an arc of radius |distance| about the corner; what the offset swallows (concave
// corners, a groove narrower than twice the distance, an arc smaller than the distance on its
// inner side) is cut away where the offset crosses itself. Empty when the rest is not one chain.
std::optional<std::vector<PlanarSegment>> offsetOpenChain(const std::vector<PlanarSegment>& chain,
                                                          double distance);

// Offsets an open chain by an axis-parallel box (the boundary of the chain swept by the box, on
// the side `side` of its travel: +1 left, -1 right): each element moves by the box corner its
// normal points to, so a direction's allowance applies only where the chain faces that way;
// convex corners are joined along the box's edges, what the box swallows is cut away. The box
// holds the origin (min <= 0 <= max). Empty when the rest is not one chain.
std::optional<std::vector<PlanarSegment>> offsetOpenChainByBox(
    const std::vector<PlanarSegment>& chain, Box2 box, double side);

// The chain up to the point where it first crosses the line `coordinate axis (0: u, 1: v) =
// limit` moving in `direction` (+1 or -1) along that axis; empty when it starts beyond it.
std::vector<PlanarSegment> chainUpTo(const std::vector<PlanarSegment>& chain, int axis,
                                     double limit, double direction);

}  // namespace kerf
