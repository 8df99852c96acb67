#pragma once

#include "core/geometry/axes.h"

namespace kerf::fagor {

// Where the theoretical tip P lies seen from the nose centre C, per location code F0-F9, in units
// of the nose radius: P = C + R * (x along X, z along Z). The seed lost the figure; this is the
// standard tip-position convention with the manual's numbering (odd codes are the corners a tool
// is calibrated on by two faces, F3 the external turning tool): docs/fagor.md, "Location codes".
struct TipDirection {
    double x = 0.0;
    double z = 0.0;
};

TipDirection tipDirection(int locationCode);

}  // namespace kerf::fagor
