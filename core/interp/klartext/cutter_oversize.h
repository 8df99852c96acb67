#pragma once

#include "core/geometry/axes.h"

// LN (3D tool compensation): where the tip of a cutter that differs from the CAM system's by the
// oversizes DR and DR2 goes so that it touches the surface where the CAM system's cutter touched
// it. The cutter is a torus: its corner radius R2 sweeps a circle of radius R - R2 about the
// tool axis at the height R2 above the tip (R2 = 0 an end mill, R2 = R a ball cutter). Pure.
namespace kerf::klartext {

// The tip's displacement for the surface normal `normal` (unit, out of the material) and the
// tool axis `tool` (unit, from the tip up the tool). The centre of the corner arc that touches
// the surface moves by DR2 along the normal, the tip follows DR2 below it along the tool, and the
// corner circle's radius R - R2 grows by DR - DR2 away from the contact, across the tool axis.
Vec3 cutterOversizeOffset(const Vec3& normal, const Vec3& tool, double dr, double dr2);

}  // namespace kerf::klartext
