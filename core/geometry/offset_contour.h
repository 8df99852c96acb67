#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/geometry/axes.h"

// The start of the contour engine (docs/contours.md): closed chains of lines and arcs in the
// working plane and their exact offsets. An offset of a line is a line and an offset of an arc
// is an arc, so machining paths built from offsets reach the canonical stream as arcs.
namespace kerf {

// A line or a circular arc in the plane (u, v). Arcs: `sweep` signed, positive counter-clockwise.
struct PlanarSegment {
    enum class Kind : uint8_t { Line, Arc };
    Kind kind = Kind::Line;
    Vec2 start{0.0, 0.0};
    Vec2 end{0.0, 0.0};
    Vec2 center{0.0, 0.0};
    double sweep = 0.0;

    static PlanarSegment line(const Vec2& start, const Vec2& end);
    static PlanarSegment arc(const Vec2& start, const Vec2& center, double sweep);

    double radius() const { return (start - center).norm(); }
    double length() const;
    // Unit direction of travel at the start and at the end.
    Vec2 startTangent() const;
    Vec2 endTangent() const;
    PlanarSegment reversed() const;
    // Shortest distance from a point to the segment.
    double distanceTo(const Vec2& p) const;
};

// A closed chain: each segment starts where the previous one ends, the last ends at the first's
// start. Counter-clockwise chains enclose the area on their left.
struct ClosedContour {
    std::vector<PlanarSegment> segments;

    bool empty() const { return segments.empty(); }
    // Twice the signed area's sign convention: positive for counter-clockwise chains.
    double signedArea() const;
    ClosedContour reversed() const;
    // Rotated by `angleRad` about the origin, then moved by `offset`.
    ClosedContour placed(const Vec2& offset, double angleRad) const;
    double distanceTo(const Vec2& p) const;
};

// Rectangle centred on the origin, sides `length` (u) by `width` (v), every corner rounded with
// `cornerRadius` (clamped to half the shorter side) or, when `cornerRadius` < 0, cut by a 45°
// chamfer of that leg length. Counter-clockwise, starting at the middle of the +u side (on the
// end arc when the corner radius takes the whole width). Zero-length lines are left out, so
// length = width = 2 x radius is a circle of four quarter arcs.
ClosedContour roundedRectangle(double length, double width, double cornerRadius);

// A circular slot: the band of `width` about the arc of radius `pitchRadius` about the origin from
// `startRad` over `sweepRad` (> 0, counter-clockwise), its ends rounded with half the width.
// Counter-clockwise, starting at the middle of the end cap at startRad + sweepRad, where the
// pitch arc's tangent leaves the slot; the inner wall is a clockwise arc joined tangentially.
ClosedContour arcSlot(double pitchRadius, double startRad, double sweepRad, double width);

// Regular polygon of `corners` corners on the circle of `circumradius` about the origin, one
// side crossing the +u axis at right angles (corners at 180/n + k 360/n degrees), each corner
// rounded with `cornerRadius` or, when it is < 0, cut by a chamfer of that leg length along each
// side. Counter-clockwise from the middle of the side on the +u axis. Empty when the rounding
// or chamfer needs more than half a side, or for fewer than 3 corners.
std::optional<ClosedContour> regularPolygon(double circumradius, int corners, double cornerRadius);

// Intersections of the carriers (infinite line, full circle) of two segments.
std::vector<Vec2> carrierIntersections(const PlanarSegment& a, const PlanarSegment& b);

// Circle about the origin, counter-clockwise from angle 0.
ClosedContour circleContour(double radius);

// Offsets a counter-clockwise chain by `distance` (positive outwards). Every corner must be
// convex or tangent (concave stretches only as tangent clockwise arcs, as in a circular slot).
// Outwards, convex corners get arcs about the corner; inwards, arcs shrink and vanish and the
// neighbours are cut at their intersection. Empty when the inward offset vanishes, when it would
// change the topology, or at a sharp concave corner (the general case is for the Clipper-based
// engine, docs/contours.md).
std::optional<ClosedContour> offsetClosed(const ClosedContour& contour, double distance);

}  // namespace kerf
