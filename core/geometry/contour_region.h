#pragma once

#include <vector>

#include "core/geometry/offset_contour.h"

// Areas bounded by closed chains of lines and arcs, their booleans and offsets (docs/contours.md).
// Clipper decides the topology on polygons flattened within a fraction of a micrometre; the result
// is rebuilt from the exact lines and arcs it came from (an offset of an arc is an arc, a corner
// of an outward offset is an arc about the corner), cut at their exact intersections.
namespace kerf {

// The engine works on an integer grid of 1 nm: coordinates must stay within this many mm of the
// origin (far beyond any machine; the callers refuse contours outside it).
inline constexpr double kMaxContourCoordinateMm = 1e6;

// Outer boundaries counter-clockwise, holes clockwise: the area lies left of every boundary.
struct Region {
    std::vector<ClosedContour> boundaries;

    bool empty() const { return boundaries.empty(); }
    double area() const;
    // Inside (boundary points count as inside within 1 µm).
    bool contains(const Vec2& p) const;
};

// The area a closed chain encloses, whatever its direction.
Region regionOf(const ClosedContour& contour);

Region unite(const Region& a, const Region& b);
// The union of all, in one boolean (overlapping regions need not be united one by one).
Region uniteAll(const std::vector<Region>& regions);
Region subtract(const Region& a, const Region& b);
Region intersect(const Region& a, const Region& b);

// Every point within `distance` of the region (> 0), or every point at least -distance inside
// it (< 0). Pieces that vanish are gone; a region may split into several.
Region offsetRegion(const Region& region, double distance);

// The same closed path, starting at its point nearest to `p` (a segment there is split).
ClosedContour startingNearest(const ClosedContour& contour, const Vec2& p);

// True when the straight line from `a` to `b` lies inside (boundary points count, as for
// `contains`).
bool containsLine(const Region& region, const Vec2& a, const Vec2& b);

// True when the chain crosses or touches itself.
bool selfIntersects(const ClosedContour& contour);

}  // namespace kerf
