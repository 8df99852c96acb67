#pragma once

#include "core/geometry/axes.h"

namespace kerf {

// Working planes. Each is named by its two in-plane axes in right-handed order, so that a positive
// rotation about the normal axis (DR+, G03) turns the first axis towards the second.
enum class Plane : uint8_t { XY, YZ, ZX };

struct PlaneAxes {
    Axis first;
    Axis second;
    Axis normal;
};

// Inline: called several times for every block.
inline PlaneAxes planeAxes(Plane plane) {
    switch (plane) {
        case Plane::YZ:
            return {Axis::Y, Axis::Z, Axis::X};
        case Plane::ZX:
            return {Axis::Z, Axis::X, Axis::Y};
        case Plane::XY:
            break;
    }
    return {Axis::X, Axis::Y, Axis::Z};
}
// The working plane perpendicular to a tool axis (Z -> XY, X -> YZ, Y -> ZX).
Plane planeForToolAxis(Axis toolAxis);
// The plane spanned by two axes given in any order, if they span one of the three.
std::optional<Plane> planeFromAxes(Axis a, Axis b);
const char* planeName(Plane plane);

// Coordinates of a 3D point in a plane's (first, second, normal) frame, and back.
Vec3 toPlaneFrame(Plane plane, const Vec3& p);
Vec3 fromPlaneFrame(Plane plane, const Vec3& q);

}  // namespace kerf
