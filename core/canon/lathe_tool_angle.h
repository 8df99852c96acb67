#pragma once

#include "core/canon/commands.h"

// The nose angle of a lathe tool's canonical geometry: an insert's nose angle or a drill's point
// angle (FAGOR NOSEA of the tool table; 0: none given).
// [choice] It travels in ToolGeometry::radius2Mm, a mill cutter's corner radius that a lathe
// offset (locationCode >= 0) has no use for, until ToolGeometry gets a field of its own: that is
// a change of core/canon/commands.h, which most of the tree includes. Read and write it through
// these two functions only.
namespace kerf::canon {

inline double latheNoseAngleDeg(const ToolGeometry& geometry) {
    return geometry.locationCode >= 0 ? geometry.radius2Mm : 0.0;
}

inline void setLatheNoseAngle(ToolGeometry& geometry, double degrees) {
    geometry.radius2Mm = degrees;
}

}  // namespace kerf::canon
