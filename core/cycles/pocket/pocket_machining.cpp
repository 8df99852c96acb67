#include "core/cycles/pocket/pocket_machining.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"

namespace kerf::cycles::pocket {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr size_t kMaxRings = 10000;

// The clearing of one region: the core and the rings around it, innermost first, local frame.
struct Clearing {
    PlanarSegment core;
    std::vector<ClosedContour> rings;
};

// The tool-centre region: the shape offset inwards by `inset`.
std::optional<CycleError> planClearing(const MillingSetup& s, const PocketShape& shape,
                                       double inset, bool climb, Clearing& out) {
    const double half = shape.halfWidth - inset;
    if (half < -1e-9) return toolTooLarge(s.cycle);
    out.core = shape.core;
    out.rings.clear();
    if (half <= 1e-9) return std::nullopt;
    const double step = s.overlap * s.tool.radius;
    const double count = std::ceil(half / step - 1e-9);
    if (count > static_cast<double>(kMaxRings)) return tooManyMoves(s.cycle);
    const int n = static_cast<int>(count);
    for (int k = n - 1; k >= 0; --k) {
        auto ring = offsetClosed(shape.contour, -(inset + half * k / n));
        if (!ring) return toolTooLarge(s.cycle);
        out.rings.push_back(climb ? std::move(*ring) : ring->reversed());
    }
    return std::nullopt;
}

// Moves along a placed core segment from its start (a point when it has no length).
void followCore(CyclePath& path, const PlanarSegment& core, const Feed& feed) {
    if (core.kind == PlanarSegment::Kind::Arc) {
        path.arc({core.end.x(), core.end.y(), path.w()}, core.center, core.sweep, feed);
    } else {
        path.moveUv(core.end, feed);
    }
}

PlanarSegment placedSegment(const Placement& place, const PlanarSegment& s) {
    ClosedContour one;
    one.segments.push_back(s);
    return place.contour(one).segments.front();
}

// Runs a clearing at the current height: core, stepover, rings.
void runClearing(CyclePath& path, const Clearing& c, const Placement& place, const Feed& feed,
                 double edgeOffset) {
    const PlanarSegment core = placedSegment(place, c.core);
    path.moveUv(core.start, feed);
    followCore(path, core, feed);
    for (const ClosedContour& ring : c.rings) {
        const ClosedContour placed = place.contour(ring);
        path.moveUv(placed.segments.front().start, feed);
        followContour(path, placed, feed, edgeOffset);
    }
}

// Helix of radius `radius` about `centre` from the current height to `toW`, starting at the
// current point (which lies on the circle); `pitch` signed, positive when moving down in w.
void helixDown(CyclePath& path, const Vec2& centre, double radius, double toW, double pitch,
               bool ccw, const Feed& feed) {
    const double turns = (path.w() - toW) / pitch;
    const double dir = ccw ? 1.0 : -1.0;
    const Vec2 from = path.uv() - centre;
    const double startAngle = std::atan2(from.y(), from.x());
    const auto whole = static_cast<size_t>(std::floor(turns + 1e-9));
    const double rest = turns - static_cast<double>(whole);
    double w = path.w();
    for (size_t i = 0; i < whole; ++i) {
        w = (i + 1 == whole && rest <= 1e-9) ? toW : w - pitch;
        path.arc({path.uv().x(), path.uv().y(), w}, centre, dir * kTwoPi, feed);
    }
    if (rest > 1e-9) {
        const double angle = startAngle + dir * kTwoPi * rest;
        const Vec2 end = centre + radius * Vec2(std::cos(angle), std::sin(angle));
        path.arc({end.x(), end.y(), toW}, centre, dir * kTwoPi * rest, feed);
    }
}

// The part of the core from its start that is `length` long; a line core may run on beyond its
// end (into the region's end, which has room for half its width).
PlanarSegment corePrefix(const PlanarSegment& core, double length) {
    if (core.kind == PlanarSegment::Kind::Arc) {
        const double sweep = (core.sweep >= 0.0 ? 1.0 : -1.0) * length / core.radius();
        return PlanarSegment::arc(core.start, core.center, sweep);
    }
    const Vec2 axis =
        core.length() > 1e-9 ? Vec2((core.end - core.start).normalized()) : Vec2(1.0, 0.0);
    return PlanarSegment::line(core.start, core.start + length * axis);
}

}  // namespace

PocketShape roundedPocket(double length, double width, double cornerRadius) {
    PocketShape shape;
    shape.contour = roundedRectangle(length, width, cornerRadius);
    shape.halfWidth = std::min(length, width) / 2.0;
    // The core lies where the offset by half the shorter side shrinks to: along the longer side.
    const double coreHalf = std::fabs(length - width) / 2.0;
    shape.core = length >= width ? PlanarSegment::line({-coreHalf, 0.0}, {coreHalf, 0.0})
                                 : PlanarSegment::line({0.0, -coreHalf}, {0.0, coreHalf});
    return shape;
}

std::optional<CycleError> machinePocket(const MillingSetup& s, const PocketShape& shape,
                                        CyclePath& path) {
    if (s.depth == 0.0) return std::nullopt;  // depth 0: not executed
    const double radius = s.tool.radius;
    const Placement& place = shape.placement;
    const Vec2 start = path.uv();
    const HoleLevels& l = s.levels;
    // Roughing leaves both allowances; finishing removes them.
    Clearing rough;
    if (auto e = planClearing(s, shape, radius + s.sideAllowance, s.climb, rough)) return e;
    const double roughDepth = std::max(0.0, s.depth - s.floorAllowance);
    std::vector<double> roughLevels;
    if (s.rough) {
        if (auto e = stepLevels(s, 0.0, roughDepth, s.infeed, roughLevels)) return e;
    }
    const Vec2 plungeLocal = shape.plungeAtCoreStart ? shape.core.start : Vec2(0.0, 0.0);
    const Vec2 plungePoint = place.point(plungeLocal);
    // Plunging strategy: helix of radius R about the plunge point, or strokes along the core
    // from its start, 2 x the tool diameter long (or Q202 / tan(ANGLE) when longer).
    const double tanAngle = std::tan(s.tool.plungeAngleDeg * std::numbers::pi / 180.0);
    const double halfFree = shape.halfWidth - radius - s.sideAllowance;
    if (s.rough && s.plunge == Plunge::Helical && halfFree < radius - 1e-9) {
        return CycleError{"cycle-plunge",
                          KERF_TR_NOOP("cycle {1}: no room for the helical plunge: the helix "
                                       "needs a diameter of twice the tool diameter"),
                          {std::to_string(s.cycle)}};
    }
    PlanarSegment stroke = PlanarSegment::line(plungeLocal, plungeLocal);
    if (s.rough && s.plunge == Plunge::Reciprocating) {
        // A line core may run on into the region's rounded end; an arc core may not.
        const double beyond = shape.core.kind == PlanarSegment::Kind::Line ? halfFree : 0.0;
        const double room = shape.core.length() + std::max(0.0, beyond);
        const double wanted = std::max(4.0 * radius, s.infeed / tanAngle);
        if (room < 4.0 * radius - 1e-9) {
            return CycleError{"cycle-plunge",
                              KERF_TR_NOOP("cycle {1}: no room for reciprocating plunging: it "
                                           "needs a length of twice the tool diameter"),
                              {std::to_string(s.cycle)}};
        }
        stroke = placedSegment(place, corePrefix(shape.core, std::min(wanted, room)));
    }

    // Positioning: clear of the workpiece at the 2nd set-up clearance first (spec 1.6).
    if ((path.w() - l.top) * l.up < 0.0) path.rapidW(l.top);
    Vec2 firstPoint = plungePoint;
    if (s.plunge == Plunge::Reciprocating) firstPoint = stroke.start;
    if (s.plunge == Plunge::Helical) firstPoint = place.point(plungeLocal + Vec2(radius, 0.0));
    // Before a straight move in the plane from one place of the region to another.
    auto travel = [&](const Vec2& to) {
        const bool below = (path.w() - l.clearance) * l.up < 0.0;
        if (!shape.convex && below && (path.uv() - to).norm() > 1e-9) path.rapidW(l.clearance);
        path.rapidUv(to);
    };
    double previous = l.surface;
    for (double level : roughLevels) {
        travel(firstPoint);
        path.rapidW(previous + l.up * s.setUpClearance);
        switch (s.plunge) {
            case Plunge::Vertical:
                path.moveW(level, s.plungeFeed);
                break;
            case Plunge::Helical:
                helixDown(path, plungePoint, radius, level, l.up * kTwoPi * radius * tanAngle,
                          s.climb, s.plungeFeed);
                break;
            case Plunge::Reciprocating:
                reciprocateDown(path, stroke, level, l.up * stroke.length() * tanAngle,
                                s.plungeFeed);
                break;
        }
        runClearing(path, rough, place, s.mill, s.feedReference == 3 ? radius : 0.0);
        path.rapidW(level + l.up * s.setUpClearance);
        previous = level;
    }

    // Side finishing: the walls at Q338 infeeds down to the floor, approached and left on
    // quarter arcs from the inside.
    if (s.finish && s.sideAllowance > 0.0) {
        auto wall = offsetClosed(shape.contour, -radius);
        const double wallHalf = shape.halfWidth - radius;
        if (wall && wallHalf > 1e-9) {
            const ClosedContour ring = place.contour(s.climb ? *wall : wall->reversed());
            // Inwards: to the left of a counter-clockwise ring, to the right of a clockwise one.
            const Vec2 t = ring.segments.front().startTangent();
            const Vec2 inward = s.climb ? Vec2(-t.y(), t.x()) : Vec2(t.y(), -t.x());
            const double arcRadius = std::min(radius, wallHalf / 2.0);
            std::vector<double> levels;
            if (auto e = stepLevels(s, 0.0, s.depth, s.finishInfeed, levels)) return e;
            const Vec2 entry = approachStart(ring, inward, arcRadius);
            const double roughFloor = l.at(roughDepth);
            for (double level : levels) {
                // The pocket is roughed (spec: with Q215 = 2 beforehand): down at rapid to the
                // set-up clearance above the level, or above the roughed floor if that is higher.
                const double above = (level - roughFloor) * l.up > 0.0 ? level : roughFloor;
                travel(entry);
                path.rapidW(above + l.up * s.setUpClearance);
                path.moveW(level, s.plungeFeed);
                approachArc(path, ring, inward, arcRadius, s.finishFeed);
                followContour(path, ring, s.finishFeed, s.feedReference >= 1 ? radius : 0.0);
                departureArc(path, ring, inward, arcRadius, s.finishFeed);
                path.rapidW(level + l.up * s.setUpClearance);
            }
        }
    }
    // Floor finishing: the roughing clearing at the floor.
    if (s.finish && s.floorAllowance > 0.0) {
        const double floor = l.at(s.depth);
        const Vec2 entry = place.point(shape.core.start);
        travel(entry);
        // Down at rapid to the set-up clearance above the roughed floor, never up to it.
        const double above = l.at(roughDepth) + l.up * s.setUpClearance;
        if ((path.w() - above) * l.up > 0.0) path.rapidW(above);
        path.moveW(floor, s.plungeFeed);
        runClearing(path, rough, place, s.finishFeed, s.feedReference >= 2 ? radius : 0.0);
        path.rapidW(floor + l.up * s.setUpClearance);
    }
    path.rapidW(l.top);
    if (shape.returnToStart) path.rapidUv(start);
    return std::nullopt;
}

}  // namespace kerf::cycles::pocket
