#pragma once

#include <optional>
#include <vector>

#include "core/geometry/contour_element.h"
#include "core/interp/path/path_move.h"

namespace kerf::interp {

// The coordinates the path builder works in when they are not the machine's axes: the tool tip
// on the part while TCPM turns the tables (the axes then follow the tip non-linearly), or the
// tilted plane a swivel head turns out of the machine's planes (an affine turn). Lines and arcs
// stay exact there, so roundings and radius compensation work as in any plane; on the way out
// each element becomes straight pieces of the machine's axes.
class PathSpace {
public:
    virtual ~PathSpace() = default;
    virtual Pose toMachine(const Pose& path) const = 0;
    virtual Pose toPath(const Pose& machine) const = 0;
    // Where the element is at `t` (0 start, 1 end): its own interpolation of every axis, unless
    // the space steers the tool's orientation itself (TCPM PATHCTRL VECTOR).
    virtual Pose along(const ContourElement& element, double t) const { return element.poseAt(t); }
    // How far a pose the axes pass (path coordinates) is from the one meant: the tip's distance;
    // a space that steers the orientation adds how far the tool's axis is off.
    virtual double deviation(const Pose& passed, const Pose& meant) const {
        return (passed.xyz() - meant.xyz()).norm();
    }
    // True: F is the feed along the element (TCPM F TCP); false: the feed of the axes as the
    // planner counts them (F CONT).
    virtual bool feedAlongElement() const { return true; }
    // Why the axes may not stand at `machine`, a piece end inside an element (a rotary axis
    // beyond its soft limit while TCPM turns it through the element); none by default. The
    // element then leaves nothing.
    virtual std::optional<PathError> refusePiece(const Pose& /*machine*/,
                                                 const SourceLocation& /*location*/) const {
        return std::nullopt;
    }
};

// One straight piece of the machine's axes and the feed that keeps the programmed feed along the
// element (F scaled by the axes' length over the element's length of the piece).
struct MachinePiece {
    Pose target;
    double feed = 0.0;
};

// More pieces than this for one element: it turns too far for the tolerance.
inline constexpr int kMaxMachinePieces = 1 << 16;

// Splits `element` (path coordinates) into the fewest pieces, a power of two, whose straight
// moves of the axes stay within `toleranceMm` of the element at the middle of each piece and,
// where a rotary axis turns more than a quarter turn in a piece, at least every quarter turn (seen
// back in path coordinates). The pieces so follow the axes along the whole element, which is what
// the soft-limit check of the planner sees. False (and `out` unchanged) when more than
// kMaxMachinePieces would be needed. Pure; any thread.
bool machinePieces(const PathSpace& space, const ContourElement& element, double feed,
                   double toleranceMm, std::vector<MachinePiece>& out);

}  // namespace kerf::interp
