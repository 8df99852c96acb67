#include "core/geometry/plane.h"

namespace kerf {

Plane planeForToolAxis(Axis toolAxis) {
    switch (toolAxis) {
        case Axis::X:
        case Axis::U:
            return Plane::YZ;
        case Axis::Y:
        case Axis::V:
            return Plane::ZX;
        default:
            return Plane::XY;
    }
}

std::optional<Plane> planeFromAxes(Axis a, Axis b) {
    auto is = [&](Axis p, Axis q) { return (a == p && b == q) || (a == q && b == p); };
    if (is(Axis::X, Axis::Y)) return Plane::XY;
    if (is(Axis::Y, Axis::Z)) return Plane::YZ;
    if (is(Axis::Z, Axis::X)) return Plane::ZX;
    return std::nullopt;
}

const char* planeName(Plane plane) {
    switch (plane) {
        case Plane::XY:
            return "XY";
        case Plane::YZ:
            return "YZ";
        case Plane::ZX:
            return "ZX";
    }
    return "XY";
}

Vec3 toPlaneFrame(Plane plane, const Vec3& p) {
    PlaneAxes axes = planeAxes(plane);
    return {p[axisIndex(axes.first)], p[axisIndex(axes.second)], p[axisIndex(axes.normal)]};
}

Vec3 fromPlaneFrame(Plane plane, const Vec3& q) {
    PlaneAxes axes = planeAxes(plane);
    Vec3 p;
    p[axisIndex(axes.first)] = q.x();
    p[axisIndex(axes.second)] = q.y();
    p[axisIndex(axes.normal)] = q.z();
    return p;
}

}  // namespace kerf
