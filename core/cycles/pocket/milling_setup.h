#pragma once

#include <optional>
#include <vector>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_path.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/geometry/offset_contour.h"

// What the pocket, stud and slot cycles 251-258 share (spec §4 intro): the operation, the
// allowances, the depth levels, the feeds and the milling direction, read once per call.
namespace kerf::cycles::pocket {

enum class Plunge : uint8_t { Vertical = 0, Helical = 1, Reciprocating = 2 };

struct MillingSetup {
    int cycle = 0;
    bool rough = true;   // Q215 0 or 1
    bool finish = true;  // Q215 0 or 2
    double sideAllowance = 0.0;
    double floorAllowance = 0.0;
    double infeed = 0.0;        // Q202, limited to LCUTS; 0: one infeed
    double finishInfeed = 0.0;  // Q338; 0: one infeed
    double overlap = 1.0;       // Q370
    Plunge plunge = Plunge::Vertical;
    int feedReference = 0;  // Q439
    Feed mill;
    Feed plungeFeed;
    Feed finishFeed;
    HoleLevels levels;
    double depth = 0.0;           // |Q201|
    double setUpClearance = 0.0;  // Q200
    bool climb = true;            // Q351 after a mirror image
    ToolInfo tool;
};

// Reads the shared parameters; a parameter the cycle does not have reads as its default.
// Checks the depth sign, the tool radius and the plunge strategy against the tool's ANGLE.
std::optional<CycleError> readSetup(int cycle, const CycleValues& values,
                                    const CycleContext& context, MillingSetup& setup);

// Tool-axis coordinates of passes from `fromDepth` to `toDepth` (both >= 0 into the material)
// in steps of at most `step` (0: one step), the last at `toDepth`.
std::optional<CycleError> stepLevels(const MillingSetup& setup, double fromDepth, double toDepth,
                                     double step, std::vector<double>& levels);

// Where a cycle's shape lies: its local (u, v) rotated by `angleRad` and moved to `origin`.
struct Placement {
    Vec2 origin{0.0, 0.0};
    double angleRad = 0.0;

    Vec2 point(const Vec2& local) const;
    ClosedContour contour(const ClosedContour& local) const {
        return local.placed(origin, angleRad);
    }
};

// Follows a placed closed contour from its start at the current tool-axis height, one arc per
// run of arcs with the same centre and radius. With `edgeOffset` != 0 the feed refers to the
// cutting edge: arcs are run at feed x r / (r + edgeOffset) (Q439 in a pocket: +R).
void followContour(CyclePath& path, const ClosedContour& contour, const Feed& feed,
                   double edgeOffset);

// A quarter arc of radius `radius` that ends at the contour's start tangent to it, coming from
// the side `normal` points to; and the mirror one that leaves it at its end.
Vec2 approachStart(const ClosedContour& contour, const Vec2& normal, double radius);
void approachArc(CyclePath& path, const ClosedContour& contour, const Vec2& normal, double radius,
                 const Feed& feed);
void departureArc(CyclePath& path, const ClosedContour& contour, const Vec2& normal, double radius,
                  const Feed& feed);

// Zig-zag along `stroke` down to `toW`, dropping at most `drop` per stroke (signed like the
// infeed), then strokes at the depth back to the stroke's start.
void reciprocateDown(CyclePath& path, const PlanarSegment& stroke, double toW, double drop,
                     const Feed& feed);

CycleError toolTooLarge(int cycle);

}  // namespace kerf::cycles::pocket
