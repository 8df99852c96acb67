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

// The clearing of one region: the core line (a point for a circle) and the rings around it,
// all in the shape's local frame, innermost first. Ring k starts k stepovers beyond the core's
// +u end on the u axis, so each ring is reached by a straight stepover.
struct Clearing {
    Vec2 coreStart{0.0, 0.0};
    Vec2 coreEnd{0.0, 0.0};
    std::vector<ClosedContour> rings;
};

// The tool-centre region: the shape offset inwards by `inset`.
std::optional<CycleError> planClearing(const MillingSetup& s, const PocketShape& shape,
                                       double inset, bool climb, Clearing& out) {
    const double length = shape.length - 2.0 * inset;
    const double width = shape.width - 2.0 * inset;
    if (width < -1e-9 || length < -1e-9) return toolTooLarge(s.cycle);
    const double shorter = std::max(0.0, std::min(length, width));
    const double half = shorter / 2.0;
    const double coreHalf = std::max(0.0, std::fabs(length - width) / 2.0);
    // The core runs along the longer side.
    const Vec2 axis = length >= width ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
    out.coreStart = -coreHalf * axis;
    out.coreEnd = coreHalf * axis;
    out.rings.clear();
    if (half <= 1e-9) return std::nullopt;
    const ClosedContour shapeContour =
        roundedRectangle(shape.length, shape.width, shape.cornerRadius);
    const double step = s.overlap * s.tool.radius;
    const double count = std::ceil(half / step - 1e-9);
    if (count > static_cast<double>(kMaxRings)) return tooManyMoves(s.cycle);
    const int n = static_cast<int>(count);
    for (int k = n - 1; k >= 0; --k) {
        auto ring = offsetConvex(shapeContour, -(inset + half * k / n));
        if (!ring) return toolTooLarge(s.cycle);
        out.rings.push_back(climb ? std::move(*ring) : ring->reversed());
    }
    // A ring along the shorter side starts on the u axis too: the contour starts at +u.
    if (axis.y() != 0.0) out.coreStart = out.coreEnd = Vec2(0.0, 0.0);
    return std::nullopt;
}

// Runs a clearing at the current height: core, stepover, rings.
void runClearing(CyclePath& path, const Clearing& c, const Placement& place, const Feed& feed,
                 double edgeOffset) {
    path.moveUv(place.point(c.coreStart), feed);
    path.moveUv(place.point(c.coreEnd), feed);
    for (const ClosedContour& ring : c.rings) {
        const ClosedContour placed = place.contour(ring);
        path.moveUv(placed.segments.front().start, feed);
        followContour(path, placed, feed, edgeOffset);
    }
}

// Helix of radius `radius` about `centre` from the current height down to `toW`, starting at
// the current point (which lies on the circle).
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

// Zig-zag between a and b down to `toW`, then one stroke at the depth to flatten the ramp.
void reciprocateDown(CyclePath& path, const Vec2& a, const Vec2& b, double toW, double drop,
                     const Feed& feed) {
    bool towardsB = true;
    while (path.w() > toW + 1e-9) {
        const double w = std::max(toW, path.w() - drop);
        const Vec2 target = towardsB ? b : a;
        path.move({target.x(), target.y(), w}, feed);
        towardsB = !towardsB;
    }
    const Vec2 target = towardsB ? b : a;
    path.moveUv(target, feed);
}

}  // namespace

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
    const Vec2 centre = place.point(Vec2(0.0, 0.0));
    const Vec2 plungeLocal = shape.plungeAtSlotEnd ? rough.coreStart : Vec2(0.0, 0.0);
    const Vec2 plungePoint = place.point(plungeLocal);
    // Plunging strategy: helix of radius R about the plunge point, or strokes along the core
    // from its start, 2 x the tool diameter long (or Q202 / tan(ANGLE) when longer).
    const double tanAngle = std::tan(s.tool.plungeAngleDeg * std::numbers::pi / 180.0);
    const double halfFree = std::min(shape.length, shape.width) / 2.0 - radius - s.sideAllowance;
    if (s.rough && s.plunge == Plunge::Helical && halfFree < radius - 1e-9) {
        return CycleError{"cycle-plunge",
                          KERF_TR_NOOP("cycle {1}: no room for the helical plunge: the helix "
                                       "needs a diameter of twice the tool diameter"),
                          {std::to_string(s.cycle)}};
    }
    Vec2 strokeA = place.point(rough.coreStart);
    Vec2 strokeB = strokeA;
    if (s.rough && s.plunge == Plunge::Reciprocating) {
        const Vec2 axis = (rough.coreEnd - rough.coreStart).norm() > 1e-9
                              ? Vec2((rough.coreEnd - rough.coreStart).normalized())
                              : Vec2(1.0, 0.0);
        const double room = (rough.coreEnd - rough.coreStart).norm() + std::max(0.0, halfFree);
        const double wanted = std::max(4.0 * radius, s.infeed / tanAngle);
        if (room < 4.0 * radius - 1e-9) {
            return CycleError{"cycle-plunge",
                              KERF_TR_NOOP("cycle {1}: no room for reciprocating plunging: it "
                                           "needs a length of twice the tool diameter"),
                              {std::to_string(s.cycle)}};
        }
        strokeB = place.point(rough.coreStart + std::min(wanted, room) * axis);
    }

    // Positioning: clear of the workpiece at the 2nd set-up clearance first (spec 1.6).
    if ((path.w() - l.top) * l.up < 0.0) path.rapidW(l.top);
    Vec2 firstPoint = plungePoint;
    if (s.plunge == Plunge::Reciprocating) firstPoint = strokeA;
    if (s.plunge == Plunge::Helical) firstPoint = place.point(plungeLocal + Vec2(radius, 0.0));
    double previous = l.surface;
    for (double level : roughLevels) {
        path.rapidUv(firstPoint);
        path.rapidW(previous + l.up * s.setUpClearance);
        switch (s.plunge) {
            case Plunge::Vertical:
                path.moveW(level, s.plungeFeed);
                break;
            case Plunge::Helical:
                helixDown(path, plungePoint, radius, level, kTwoPi * radius * tanAngle, s.climb,
                          s.plungeFeed);
                break;
            case Plunge::Reciprocating:
                reciprocateDown(path, strokeA, strokeB, level,
                                (strokeB - strokeA).norm() * tanAngle, s.plungeFeed);
                break;
        }
        runClearing(path, rough, place, s.mill, s.feedReference == 3 ? radius : 0.0);
        path.rapidW(level + l.up * s.setUpClearance);
        previous = level;
    }

    // Side finishing: the walls at Q338 infeeds down to the floor, approached and left on
    // quarter arcs from the inside.
    if (s.finish && s.sideAllowance > 0.0) {
        auto wall =
            offsetConvex(roundedRectangle(shape.length, shape.width, shape.cornerRadius), -radius);
        const double wallHalf = std::min(shape.length, shape.width) / 2.0 - radius;
        if (wall && wallHalf > 1e-9) {
            const ClosedContour ring = place.contour(s.climb ? *wall : wall->reversed());
            const Vec2 inward = place.point({-1, 0}) - centre;
            const double arcRadius = std::min(radius, wallHalf / 2.0);
            std::vector<double> levels;
            if (auto e = stepLevels(s, 0.0, s.depth, s.finishInfeed, levels)) return e;
            const Vec2 entry = approachStart(ring, inward, arcRadius);
            const double roughFloor = l.at(roughDepth);
            for (double level : levels) {
                // The pocket is roughed (spec: with Q215 = 2 beforehand): down at rapid to the
                // set-up clearance above the level, or above the roughed floor if that is higher.
                const double above = (level - roughFloor) * l.up > 0.0 ? level : roughFloor;
                path.rapidUv(entry);
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
        const Vec2 entry = place.point(rough.coreStart);
        path.rapidUv(entry);
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
