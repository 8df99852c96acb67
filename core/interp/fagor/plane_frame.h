#pragma once

#include "core/geometry/contour_element.h"

namespace kerf::fagor {

// The working plane as programs see it: abscissa and ordinate axes (G17 X Y, G18 Z X, G19 Y Z,
// G16 a b), mapped onto the geometry's right-handed plane. A G16 pair given in the other order
// (G16 X Z) is the same geometric plane travelled the other way: G02/G03, angles and left/right
// are mirrored.
struct PlaneFrame {
    Plane plane = Plane::ZX;
    Axis abscissa = Axis::Z;
    Axis ordinate = Axis::X;
    bool reversed = false;

    static PlaneFrame standard(Plane plane) {
        const PlaneAxes axes = planeAxes(plane);
        return {plane, axes.first, axes.second, false};
    }

    Vec2 point(const Pose& pose) const { return {pose[abscissa], pose[ordinate]}; }
    void setPoint(Pose& pose, const Vec2& p) const {
        pose[abscissa] = p.x();
        pose[ordinate] = p.y();
    }
    // A point of the (abscissa, ordinate) frame in the geometry's (first, second) frame.
    Vec2 toGeometry(const Vec2& p) const { return reversed ? Vec2(p.y(), p.x()) : p; }
    Vec2 fromGeometry(const Vec2& p) const { return reversed ? Vec2(p.y(), p.x()) : p; }
    // A sweep (or turning sense) of the program frame in the geometry's frame.
    double toGeometrySweep(double sweep) const { return reversed ? -sweep : sweep; }
};

}  // namespace kerf::fagor
