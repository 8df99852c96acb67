#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "core/cycles/cycle_context.h"

// The cylinder-surface cycles 27, 28, 29 and 39 (spec §7) work on the development (the unrolled
// surface) of a cylinder of radius Q16: u along the circumference in mm, v along the cylinder
// axis, w the height above the surface along the tool (negative: into the material). This header
// holds what both the cycles and the interpreter need: the contour in mm, and the map from the
// development to the rotary table and the linear axes.
namespace kerf::cycles::cylinder {

using Chain = std::vector<PlanarSegment>;

// The contour of the subprogram with its X (the circumference) in mm: with `degrees` (Q17 = 0)
// X is an angle and becomes the arc length on `radiusMm`. Arcs of a contour in degrees are
// ellipses in mm: they become chords within `toleranceMm`.
ContourTrain unrolledInMm(const ContourTrain& train, double radiusMm, bool degrees,
                          double toleranceMm);

// The point of the chain nearest to `p`.
Vec2 nearestOnChain(const Chain& chain, const Vec2& p);

// Where the cylinder stands on the machine, in the linear axes of the canonical stream: a point
// of the rotary table's axis, the axis direction (unit), the tool direction (unit, perpendicular
// to the axis) and the cylinder radius.
struct CylinderPlacement {
    Vec3 origin{0.0, 0.0, 0.0};
    Vec3 axis{1.0, 0.0, 0.0};
    Vec3 tool{0.0, 0.0, 1.0};
    double radiusMm = 1.0;
    // Seen from outside, (circumference, axis, tool) is right-handed: a table turned by +angle
    // brings the material at u + radius * angle under the tool (ISO 841 table directions).
    Vec3 circumference() const { return axis.cross(tool); }
};

// Rotary-table angle and linear axes for a point of the development.
struct CylinderPose {
    double angleDeg = 0.0;
    Vec3 linear{0.0, 0.0, 0.0};
};

// Plain mapping (cycle 27): u turns the table, the tool stays radial. Aligned mapping (28, 29,
// 39: `aligned` is the programmed chain): the table turns to the nearest point of the chain and
// the tool is shifted sideways by the rest of u, parallel to the radial line there, so the walls
// beside the chain stay parallel to each other (spec: slot walls parallel).
CylinderPose placeOnCylinder(const CylinderPlacement& placement, const Vec3& local,
                             const Chain* aligned);

}  // namespace kerf::cycles::cylinder
