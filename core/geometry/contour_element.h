#pragma once

#include <optional>
#include <vector>

#include "core/geometry/arc_math.h"
#include "core/geometry/plane.h"

namespace kerf {

// A straight line or circular/helical arc of a contour. Geometry in the working plane is exact;
// the plane's normal axis and every other axis move linearly with the element's parameter
// t in [0, 1] (fraction of the length in the plane).
struct ContourElement {
    enum class Kind : uint8_t { Line, Arc };

    Kind kind = Kind::Line;
    Plane plane = Plane::XY;
    Pose start;
    Pose end;
    Vec2 center{0.0, 0.0};  // arcs: in-plane centre
    double sweep = 0.0;     // arcs: signed radians, positive counter-clockwise

    static ContourElement line(Plane plane, const Pose& start, const Pose& end);
    static ContourElement arc(Plane plane, const Pose& start, const Pose& end, const Vec2& center,
                              double sweep);

    Vec2 start2() const { return inPlane(start); }
    Vec2 end2() const { return inPlane(end); }
    Vec2 inPlane(const Pose& pose) const {
        const PlaneAxes axes = planeAxes(plane);
        return {pose[axes.first], pose[axes.second]};
    }
    void setInPlane(Pose& pose, const Vec2& p) const {
        const PlaneAxes axes = planeAxes(plane);
        pose[axes.first] = p.x();
        pose[axes.second] = p.y();
    }

    double radius() const { return (start2() - center).norm(); }
    double planarLength() const;
    // True when the element moves in the working plane (not only along the tool axis).
    bool movesInPlane() const {
        return kind == Kind::Arc ? planarLength() > 1e-9
                                 : (end2() - start2()).squaredNorm() > 1e-18;
    }
    Vec2 startTangent() const;
    Vec2 endTangent() const;
    Vec2 pointAt(double t) const;
    Pose poseAt(double t) const;
    // Parameter of a point on (or close to) the element; may lie outside [0, 1].
    double paramOf(const Vec2& p) const;
    // The part of the element between parameters t0 and t1 (t0 < t1).
    ContourElement sub(double t0, double t1) const;
};

// Offsets an element sideways by `distance` (positive = to the left of the direction of travel).
// Empty when an arc would shrink to nothing or turn inside out.
std::optional<ContourElement> offsetElement(const ContourElement& element, double distance);

// Intersections of the carriers of two elements (infinite line, full circle) in the plane.
std::vector<Vec2> intersectCarriers(const ContourElement& a, const ContourElement& b);

// Signed turning angle at the junction of a and b (radians, positive = left turn).
double turnAngle(const ContourElement& a, const ContourElement& b);

// Rounding arc of radius `radius` tangent to a (near its end) and b (near its start).
struct Fillet {
    double paramOnA;  // where a is cut
    double paramOnB;  // where b starts again
    Vec2 center;
    double sweep;
};
std::optional<Fillet> fillet(const ContourElement& a, const ContourElement& b, double radius);

}  // namespace kerf
