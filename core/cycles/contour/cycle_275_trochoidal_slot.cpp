// Cycle 275 TROCHOIDAL SLOT (seed 003): the contour of cycle 14 is the centre line of a slot of
// width Q219, roughed by trochoidal loops level by level and its walls finished at Q338 infeeds.
// A closed slot starts with an L block (not on a corner) and is entered reciprocating (Q366 2)
// or vertically; an open slot starts with an APPR block and is entered vertically there.
#include <cmath>
#include <numbers>

#include "core/cycles/common_parameters.h"
#include "core/cycles/contour/contour_train.h"
#include "core/cycles/contour/sl_end_position.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/contour/trochoid.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/pocket/milling_setup.h"
#include "core/cycles/pocket/pocket_parameters.h"
#include "core/geometry/arc_math.h"
#include "core/geometry/contour_region.h"
#include "core/geometry/open_chain_offset.h"

namespace kerf::cycles {

namespace {

using namespace contour;
using pocket::MillingSetup;
using pocket::Plunge;

CycleError slotError(const char* messageTemplate) {
    return contourError(275, messageTemplate);
}

// The tool-centre rings that finish the walls, `offset` from the centre line, the slot on
// their left (counter-clockwise round an open slot, the outer wall counter-clockwise and the
// inner one clockwise for a closed slot); empty when the tool does not fit.
std::vector<ClosedContour> wallRings(const ContourTrain& train, double offset) {
    const Chain& line = train.segments;
    if (train.closed) {
        const Region band = regionOf(ClosedContour{line});
        const Region outer = offsetRegion(band, offset);
        const Region inner = offsetRegion(band, -offset);
        if (outer.boundaries.size() != 1 || inner.boundaries.size() != 1) return {};
        return {outer.boundaries.front(), inner.boundaries.front().reversed()};
    }
    const auto right = offsetOpenChain(line, -offset);
    const auto left = offsetOpenChain(line, offset);
    if (!right || !left || right->empty() || left->empty()) return {};
    ClosedContour ring;
    ring.segments = *right;
    ring.segments.push_back(
        PlanarSegment::arc(right->back().end, line.back().end, std::numbers::pi));
    for (const PlanarSegment& s : reversedChain(*left))
        ring.segments.push_back(s);
    ring.segments.push_back(
        PlanarSegment::arc(left->front().start, line.front().start, std::numbers::pi));
    if (selfIntersects(ring)) return {};
    return {ring};
}

// Follows a ring with the slot on the side `bandLeft`; with `edge` the feed on its arcs refers
// to the cutting edge: the wall lies outside an arc that turns towards the slot.
void followRing(CyclePath& path, const ClosedContour& ring, bool bandLeft, double edge,
                const Feed& feed) {
    const double w = path.w();
    for (const PlanarSegment& s : ring.segments) {
        if (s.kind == PlanarSegment::Kind::Line) {
            path.moveUv(s.end, feed);
            continue;
        }
        const double r = s.radius();
        const double edgeRadius = ((s.sweep > 0.0) == bandLeft) ? r + edge : r - edge;
        Feed f = feed;
        if (edge > 0.0 && edgeRadius > 0.0 && !feed.isRapid()) f.value *= r / edgeRadius;
        path.arc({s.end.x(), s.end.y(), w}, s.center, s.sweep, f);
    }
}

std::optional<CycleError> checkSlot(const ContourTrain& train) {
    if (train.labelCount == 0) {
        return contourError(275, KERF_TR_NOOP("cycle {1} needs cycle 14 CONTOUR before it"));
    }
    if (train.labelCount > 1) {
        return slotError(
            KERF_TR_NOOP("cycle {1}: cycle 14 must list exactly one contour "
                         "subprogram (the slot's centre line)"));
    }
    if (!train.closed) return std::nullopt;
    // Seed 003: the start of a closed slot must not lie on a corner of its centre line.
    const Vec2 in = train.segments.back().endTangent();
    const Vec2 out = train.segments.front().startTangent();
    if ((in - out).norm() > 1e-6) {
        return slotError(
            KERF_TR_NOOP("cycle {1}: the start point of a closed slot must not lie "
                         "on a corner of the contour"));
    }
    return std::nullopt;
}

std::optional<CycleError> expand(const CycleValues& given, const CycleContext& ctx,
                                 CyclePath& path) {
    const ContourTrain& train = ctx.train;
    if (auto e = checkSlot(train)) return e;
    // Q366: 1 has no function; an open slot is entered vertically beside the material.
    CycleValues v = given;
    if (v.integer(366) == 1 || !train.closed) v.set(366, 0.0);
    MillingSetup s;
    if (auto e = pocket::readSetup(275, v, ctx, s)) return e;
    if (s.depth == 0.0) return std::nullopt;
    if (v.number(202) <= 0.0) {
        return slotError(
            KERF_TR_NOOP("cycle {1}: the plunging depth Q202 must be greater "
                         "than 0"));
    }
    const double radius = ctx.tool.radius;
    const double width = v.number(219);
    const double roughWidth = width - 2.0 * s.sideAllowance;
    if (roughWidth < 2.0 * radius - 1e-9) return pocket::toolTooLarge(275);
    if (roughWidth > 4.0 * radius + 1e-9) {
        return slotError(
            KERF_TR_NOOP("cycle {1}: the slot width less the side allowances is "
                         "more than twice the tool diameter"));
    }
    Trochoid loops;
    loops.loopRadius = roughWidth / 2.0 - radius;
    loops.pitch = v.number(436);
    if (loops.loopRadius > 1e-9 && loops.pitch <= 0.0) {
        return slotError(
            KERF_TR_NOOP("cycle {1}: the infeed per revolution Q436 must be "
                         "greater than 0"));
    }
    // Seed 003: Q351 takes the spindle direction into account; climb with M3 turns the loops
    // counter-clockwise.
    bool climb = s.climb;
    if (ctx.spindle == canon::SpindleDirection::CounterClockwise) climb = !climb;
    loops.counterClockwise = climb;
    loops.edgeOffset = s.feedReference == 3 ? radius : 0.0;
    const Chain& line = train.segments;
    // Each loop is two moves; a tiny pitch (Q436 = 1e-300 is in range) would list endless loops.
    if (loops.loopRadius > 1e-9 &&
        2.0 * chainLength(line) / loops.pitch >= static_cast<double>(CyclePath::kMoveLimit)) {
        return tooManyMoves(275);
    }
    const Vec2 start = line.front().start;
    const HoleLevels& l = s.levels;

    std::vector<ClosedContour> rings;
    const double wallOffset = width / 2.0 - radius;
    const bool finishWalls = s.finish && s.sideAllowance > 0.0;
    if (finishWalls) {
        rings = wallRings(train, wallOffset);
        if (rings.empty()) return pocket::toolTooLarge(275);
        if (!climb) {
            for (ClosedContour& r : rings)
                r = r.reversed();
        }
    }

    // Plunging (closed slots, Q366 2): strokes along the first line of the centre line.
    const double tanAngle = std::tan(ctx.tool.plungeAngleDeg * std::numbers::pi / 180.0);
    PlanarSegment stroke = line.front();
    if (s.plunge == Plunge::Reciprocating) {
        const double wanted = std::max(4.0 * radius, s.infeed / tanAngle);
        if (stroke.length() > wanted) {
            stroke =
                PlanarSegment::line(stroke.start, stroke.start + wanted * stroke.startTangent());
        }
    }
    auto overStart = [&](double previous) {
        if ((path.w() - l.top) * l.up < 0.0) path.rapidW(l.top);
        path.rapidUv(start);
        path.rapidW(previous + l.up * s.setUpClearance);
    };

    // Roughing, and the floor finishing at the depth with the finishing feed.
    std::vector<double> levels;
    const double roughDepth = std::max(0.0, s.depth - s.floorAllowance);
    if (s.rough) {
        if (auto e = pocket::stepLevels(s, 0.0, roughDepth, s.infeed, levels)) return e;
    }
    std::vector<Feed> feeds(levels.size(), s.mill);
    if (s.finish && s.floorAllowance > 0.0) {
        levels.push_back(l.at(s.depth));
        feeds.push_back(s.finishFeed);
    }
    double previous = l.surface;
    for (size_t k = 0; k < levels.size(); ++k) {
        overStart(previous);
        if (s.plunge == Plunge::Reciprocating) {
            path.moveW(previous, s.plungeFeed);
            pocket::reciprocateDown(path, stroke, levels[k], l.up * stroke.length() * tanAngle,
                                    s.plungeFeed);
        } else {
            path.moveW(levels[k], s.plungeFeed);
        }
        runTrochoid(path, line, loops, feeds[k]);
        path.rapidW(l.top);  // seed 003: at the end point to the clearance height
        previous = levels[k];
    }

    // Side finishing: each wall ring at Q338 infeeds to the depth, entered from the centre
    // line's start on a quarter arc from the slot side.
    if (finishWalls) {
        std::vector<double> finishLevels;
        if (auto e = pocket::stepLevels(s, 0.0, s.depth, s.finishInfeed, finishLevels)) return e;
        const double arcRadius = wallOffset / 2.0;
        const double edge = s.feedReference >= 1 ? radius : 0.0;
        overStart(l.surface);
        for (double level : finishLevels) {
            path.moveW(level, s.plungeFeed);
            for (const ClosedContour& found : rings) {
                const ClosedContour ring = startingNearest(found, start);
                const Vec2 t = ring.segments.front().startTangent();
                const Vec2 inward = climb ? leftNormal(t) : Vec2(-leftNormal(t));
                path.moveUv(pocket::approachStart(ring, inward, arcRadius), s.finishFeed);
                pocket::approachArc(path, ring, inward, arcRadius, s.finishFeed);
                followRing(path, ring, climb, edge, s.finishFeed);
                pocket::departureArc(path, ring, inward, arcRadius, s.finishFeed);
                path.moveUv(start, s.finishFeed);
            }
        }
    }
    finishSlCycle(path, ctx, l.top, l.up, Feed::rapid());
    return std::nullopt;
}

constexpr ParameterDescriptor kParameters[] = {
    pocket::kOperation,
    {.q = 219,
     .description = KERF_TR_NOOP("Slot width"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = common::kLength,
     .defaultValue = 10.0},
    pocket::kSideAllowance,
    {.q = 436,
     .description = KERF_TR_NOOP("Infeed per revolution (trochoidal loop)"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = common::kLength,
     .defaultValue = 2.0},
    pocket::kMillingFeed,
    common::kClimbOrUpCut,
    common::kDepth,
    common::kPlungingDepth,
    pocket::kPlungeFeed,
    pocket::kFinishingInfeed,
    pocket::kFinishingFeed,
    common::kSetUpClearance,
    common::kSurface,
    common::kSecondClearance,
    {.q = 366,
     .description = KERF_TR_NOOP("Plunging strategy (0 vertical, 1 no function, 2 "
                                 "reciprocating)"),
     .min = 0.0,
     .max = 2.0,
     .defaultValue = 2.0,
     .predef = true,
     .integer = true},
    common::addedLater(pocket::kFloorAllowance),
    common::addedLater(pocket::kFeedReference),
};

}  // namespace

const CycleDescriptor kCycle275{.number = 275,
                                .name = KERF_TR_NOOP("TROCHOIDAL SLOT"),
                                .group = CycleGroup::Contours,
                                .parameters = kParameters,
                                .expand = expand};

}  // namespace kerf::cycles
