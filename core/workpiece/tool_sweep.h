#pragma once

#include <variant>

#include "core/geometry/axes.h"

namespace kerf::workpiece {

// The cutting body of a milling tool about the tool axis (z): a cylinder of `radius` from the
// tip up by `length`, its bottom edge rounded by `cornerRadius` (0 flat, = radius a ball, between
// a torus). It is a core cylinder (radius - cornerRadius) dilated by cornerRadius.
struct Cutter {
    double radius = 0.0;
    double cornerRadius = 0.0;
    double length = 0.0;
};

// The tool tip moving on a straight line.
struct LineSweep {
    Vec3 from{0.0, 0.0, 0.0};
    Vec3 to{0.0, 0.0, 0.0};
};

// The tool tip moving on an arc in the plane z = const: `radius` about `centre`, from the angle
// `startRad` by the signed `sweepRad` (positive counter-clockwise); a full circle or more is an
// annulus.
struct ArcSweep {
    Vec2 centre{0.0, 0.0};
    double z = 0.0;
    double radius = 0.0;
    double startRad = 0.0;
    double sweepRad = 0.0;
};

// The volume a cutter sweeps along one path, with its bounding box.
struct Sweep {
    std::variant<LineSweep, ArcSweep> path;
    Cutter cutter;
    Vec3 boxMin{0.0, 0.0, 0.0};
    Vec3 boxMax{0.0, 0.0, 0.0};
};

Sweep sweepAlongLine(const Cutter& cutter, const Vec3& from, const Vec3& to);
Sweep sweepAlongArc(const Cutter& cutter, const ArcSweep& arc);

// The signed distance from `p` to the swept volume: exact outside it (the cutter's volume swept
// along the path, not an approximation); inside, a lower bound of the depth (negative).
double sweepDistance(const Sweep& sweep, const Vec3& p);

}  // namespace kerf::workpiece
