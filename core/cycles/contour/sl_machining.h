#pragma once

#include <optional>
#include <vector>

#include "core/cycles/contour/formula_area.h"
#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_path.h"
#include "core/geometry/contour_region.h"

// What the SL cycles 21-24 share (spec §6): cycle 20's data, the area of cycle 14's superimposed
// subcontours, the depth levels and the contour-parallel clearing of a tool-centre region.
namespace kerf::cycles::contour {

struct ContourData {     // cycle 20
    double depth = 0.0;  // |Q1|
    double up = 1.0;     // +1 when Q1 points into -w (the usual negative depth)
    double overlap = 1.0;
    double sideAllowance = 0.0;
    double floorAllowance = 0.0;
    double surface = 0.0;
    double setUpClearance = 0.0;
    double clearanceHeight = 0.0;
    double cornerRadius = 0.0;  // Q8: inside corners of the tool-centre paths rounded
    bool climb = true;          // Q9, after a mirror image

    // The tool-axis coordinate `depthBelow` (>= 0) into the material.
    double at(double depthBelow) const { return surface - up * depthBelow; }
    double aboveSurface() const { return at(-setUpClearance); }
};

std::optional<CycleError> readContourData(int cycle, const CycleContext& context, ContourData& out);

// The machined area: pockets superimposed in cycle 14's order (a pocket adds its area, or keeps
// only the common area when the first pocket starts inside it), islands taken away. Without
// any pocket, `islandsOnly` is set and `area` is the union of the islands. With a contour
// formula the area of its formula; `levels` holds it level by level (one level down to cycle
// 20's depth unless subcontours have their own DEPTH).
struct ContourArea {
    Region area;  // at the surface
    bool islandsOnly = false;
    double cornerRadius = 0.0;  // cycle 20's Q8
    std::vector<AreaLevel> levels;
    double deepest() const { return levels.back().bottom; }
};
std::optional<CycleError> combineContours(int cycle, const CycleContext& context,
                                          const ContourData& data, ContourArea& out);

// Where the tool centre may be at one of the area's levels: `inset` from every wall (outside the
// islands when islands only), with the area left of every boundary. Its convex corners (the
// inside corners of a pocket) are rounded with Q8: every point of it lies on a disc of radius Q8
// inside it.
Region toolCentreRegion(const ContourArea& area, double inset, size_t level = 0);

// The level of the area at `depthBelow` the surface.
size_t levelAt(const ContourArea& area, double depthBelow);

// Infeed depths (> 0) from `from` to `to` in steps of at most |step| (0: one), the last at `to`.
std::optional<CycleError> infeedDepths(int cycle, double from, double to, double step,
                                       std::vector<double>& out);

// One closed path of a clearing and whether the tool reaches it by a straight move at the
// depth (within the region) or must lift and plunge again.
struct ClearingPass {
    ClosedContour path;
    bool straightLink = false;
    // Nothing of it is cleared before (the innermost ring of its area: no ring of the next
    // level lies inside it): the tool cuts with its full circumference (cycle 22's Q401).
    bool fullWidth = false;
    // A helical plunge onto its start (cycle 22 with a tool ANGLE): radius 0 plunges straight.
    Vec2 helixCentre{0.0, 0.0};
    double helixRadius = 0.0;
    // Where no helix fits: a reciprocating plunge to and fro along the pass's first
    // `strokeLength` of path (0: none).
    double strokeLength = 0.0;
    // Reached at the depth along a boundary of the tool-centre region from the end of the pass
    // before (cycle 22 Q404 = 0 between rest areas) instead of straight.
    std::vector<PlanarSegment> contourLink;
    // Cycle 23: the radius of the vertical quarter arc that brings the tool down onto the start,
    // tangent to the floor (0: straight down), and the direction along the main axis u (+-1) in
    // which it meets the floor: the arc lies in the plane of the tool axis and u (Z/X).
    double approachRadius = 0.0;
    double approachDirection = 1.0;
};

// Places a helix of at most `radius` (and at least a quarter of it) for every pass reached by a
// plunge: a circle through the pass's start whose disc stays inside `region` (the outermost
// tool-centre region). Where none fits and `strokeLength` > 0, the pass plunges reciprocating
// along its own path over strokeLength (at most half the path) instead. False when some pass
// has neither.
bool placeHelices(std::vector<ClearingPass>& passes, const Region& region, double radius,
                  double strokeLength = 0.0);

// The rest area (the index of the smallest outer boundary of `region` enclosing its start) of
// each pass; region.boundaries.size() for a pass outside all of them.
std::vector<size_t> areasOfPasses(const std::vector<ClearingPass>& passes, const Region& region);

// Cycle 22 Q404 = 0: a pass that would be reached from above is reached at the depth along the
// boundary of `room` (the tool-centre region, the contour for the tool) when it and the pass
// before start on that same boundary: the shorter way round from one start to the other, or the
// longer one when the shorter passes through a rest area of `rest` (the region the passes clear)
// whose passes have not all run yet, other than the pass's own area: the tool would cut that
// area's material at the link. Both ways through such an area: the tool lifts.
void linkAlongContour(std::vector<ClearingPass>& passes, const Region& room, const Region& rest);

// Cycle 23's vertical tangential approach (spec: "if there is room"; seed: for tool axis Z in the
// Z/X plane): for every pass reached from above, a quarter arc of `radius`, else R/2 or R/4, in
// the plane of the tool axis and the main axis u, whose path in the plane (the line of that
// length along u ending at the pass's start) lies inside `region`. It meets the floor moving the
// way the pass starts along u; a pass starting across u takes +u, else -u. None fits: straight
// down.
void placeApproachArcs(std::vector<ClearingPass>& passes, const Region& region, double radius);

// How many strokes the reciprocating plunge of `pass` makes over `drop` (0: it has none).
double reciprocatingStrokes(const ClearingPass& pass, double drop, double tanAngle);

// How the clearing runs beyond its feeds: `fullWidthFactor` scales the milling feed on the passes
// that cut with the full circumference (Q401); `helixTan` > 0 plunges on the passes' helices
// descending tan(ANGLE) per unit of path.
struct ClearingOptions {
    double fullWidthFactor = 1.0;
    double helixTan = 0.0;
    bool climb = true;
};

// Contour-parallel clearing of `region` from the inside out: the region and its offsets inwards
// by `step`, innermost first, each pass starting where it is nearest to the end of the pass
// before (the first nearest to `from`). Climb: the region's own direction; up-cut: reversed.
// With a cache, a plan made before for exactly the same inputs is taken from it.
std::optional<CycleError> planClearing(int cycle, const Region& region, double step, bool climb,
                                       const Vec2& from, std::vector<ClearingPass>& out,
                                       ClearingCache* cache = nullptr);

// The last few clearing plans with their inputs (cycle 23 clears the region cycle 22 cleared).
// A plan is reused only when region, step, direction and start are exactly equal.
class ClearingCache {
public:
    const std::vector<ClearingPass>* find(const Region& region, double step, bool climb,
                                          const Vec2& from) const;
    void add(const Region& region, double step, bool climb, const Vec2& from,
             const std::vector<ClearingPass>& passes);

private:
    struct Entry {
        Region region;
        double step = 0.0;
        bool climb = true;
        Vec2 from{0.0, 0.0};
        std::vector<ClearingPass> passes;
    };
    static constexpr size_t kEntries = 4;
    std::vector<Entry> m_entries;  // newest last
};

// Where clearings start: near the first contour's start point, the same for cycles 21, 22 and 23
// wherever the tool stands, so that 21 drills where 22 plunges.
Vec2 planningStart(const CycleContext& context);

// Runs a clearing at the tool-axis coordinate `w`: the first pass from above (rapid to
// set-up clearance over the start, to `reentryW`, plunge at `plunge`), the others by their link.
void runClearing(CyclePath& path, const std::vector<ClearingPass>& passes, const ContourData& data,
                 double w, double reentryW, const Feed& mill, const Feed& plunge,
                 const ClearingOptions& options = {});

// Follows a closed path from its start at the current height.
void followPath(CyclePath& path, const ClosedContour& contour, const Feed& feed);

CycleError contourError(int cycle, const char* messageTemplate);

}  // namespace kerf::cycles::contour
