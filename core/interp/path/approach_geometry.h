#pragma once

#include <optional>
#include <vector>

#include "core/geometry/arc_math.h"
#include "core/interp/path/path_move.h"

namespace kerf::interp {

// One tool-centre move in the working plane.
struct PlanarMove {
    Vec2 end;
    bool arc = false;
    Vec2 center{0.0, 0.0};
    double sweep = 0.0;
};

// Tool-centre moves of an approach to the contour point `contourPoint` whose first element leaves
// along `tangent`, for a tool offset `offset` (signed: positive = tool left of the contour). The
// first move leads from `start` to the helper point; the rest reach the compensated contour start.
// TNC definitions: LT helper point LEN before the contour point on the tangent; LN helper point
// LEN from the contour on its normal (tool edge LEN away); CT arc of radius R (positive: centre on
// the tool side) over CCA degrees; LCT line tangent into an arc of radius R on the tool side.
std::optional<std::vector<PlanarMove>> approachMoves(ApproachKind kind, const Vec2& start,
                                                     const Vec2& contourPoint, const Vec2& tangent,
                                                     double offset, double length, double angleDeg,
                                                     double radius);

// Tool-centre moves of a departure from the contour end point `contourPoint` whose last element
// arrives along `tangent`. LCT ends at `endPoint` (tool centre).
std::optional<std::vector<PlanarMove>> departureMoves(ApproachKind kind, const Vec2& contourPoint,
                                                      const Vec2& tangent, double offset,
                                                      double length, double angleDeg, double radius,
                                                      const Vec2& endPoint);

}  // namespace kerf::interp
