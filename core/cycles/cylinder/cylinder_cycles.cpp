// Cylinder-surface cycles (spec §7, software option 1): 27 CYLINDER SURFACE, 28 SLOT MILLING, 29
// RIDGE MILLING, 39 OUTSIDE CONTOUR. They expand on the development of the cylinder (u along the
// circumference in mm, v along the axis, w above the surface: cylinder_surface.h); the
// interpreter turns the table and moves the linear axes from there. Approach and departure are
// tangential half circles (apprDepCylWall = CircleTangential).
#include <cmath>
#include <numbers>

#include "core/cycles/contour/contour_train.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/pocket/milling_setup.h"
#include "core/geometry/open_chain_offset.h"

namespace kerf::cycles {

namespace {

using namespace contour;

constexpr ParameterDescriptor kClearance{.q = 6,
                                         .description = KERF_TR_NOOP("Set-up clearance"),
                                         .unit = Unit::Millimetre,
                                         .min = 0.0,
                                         .max = kLength,
                                         .defaultValue = 2.0};
constexpr ParameterDescriptor kRadius{.q = 16,
                                      .description = KERF_TR_NOOP("Cylinder radius"),
                                      .unit = Unit::Millimetre,
                                      .min = 0.0,
                                      .max = kLength,
                                      .defaultValue = 50.0};
constexpr ParameterDescriptor kDimensionType{
    .q = 17,
    .description = KERF_TR_NOOP("Rotary-axis coordinates in the subprogram: 0 degrees, 1 mm/inch"),
    .min = 0.0,
    .max = 1.0,
    .defaultValue = 0.0,
    .integer = true};
constexpr ParameterDescriptor kSlotWidth{.q = 20,
                                         .description = KERF_TR_NOOP("Slot width"),
                                         .unit = Unit::Millimetre,
                                         .min = -kLength,
                                         .max = kLength,
                                         .defaultValue = 10.0};
constexpr ParameterDescriptor kRidgeWidth{.q = 20,
                                          .description = KERF_TR_NOOP("Ridge width"),
                                          .unit = Unit::Millimetre,
                                          .min = -kLength,
                                          .max = kLength,
                                          .defaultValue = 10.0};
constexpr ParameterDescriptor kTolerance{
    .q = 21,
    .description = KERF_TR_NOOP("Tolerance of the slot walls (0: no re-machining)"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = 9.9999,
    .defaultValue = 0.0};

constexpr ParameterDescriptor kParameters27[] = {kContourDepth,  kSideAllowance, kClearance,
                                                 kPlungingDepth, kPlungeFeed,    kMillingFeed,
                                                 kRadius,        kDimensionType};
constexpr ParameterDescriptor kParameters28[] = {
    kContourDepth, kSideAllowance, kClearance,     kPlungingDepth, kPlungeFeed,
    kMillingFeed,  kRadius,        kDimensionType, kSlotWidth,     kTolerance};
constexpr ParameterDescriptor kParameters29[] = {kContourDepth,  kSideAllowance, kClearance,
                                                 kPlungingDepth, kPlungeFeed,    kMillingFeed,
                                                 kRadius,        kDimensionType, kRidgeWidth};

// What every cylinder cycle reads first.
struct Setup {
    std::vector<double> depths;  // > 0, into the material
    double up = 1.0;             // -1 when a positive depth is allowed and programmed
    double clearance = 0.0;      // w of the set-up clearance
    Feed plunge;
    Feed mill;
    double at(double below) const { return -up * below; }
};

std::optional<CycleError> readSetup(int cycle, const CycleValues& v, const CycleContext& ctx,
                                    bool needsSide, Setup& out) {
    if (ctx.train.labelCount == 0) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1} needs cycle 14 CONTOUR before it"));
    }
    if (v.number(16) <= 0.0) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1}: the cylinder radius Q16 must be "
                                                "greater than 0"));
    }
    if (auto e = checkDepthSign(cycle, 1, v.number(1), ctx)) return e;
    if (cycle != 27 && ctx.spindle == canon::SpindleDirection::Stopped) {
        return CycleError{"cycle-spindle",
                          KERF_TR_NOOP("cycle {1} needs the spindle running (M3 or M4)"),
                          {std::to_string(cycle)}};
    }
    if (needsSide && ctx.train.side == 0) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1}: program the contour subprogram "
                                                "with radius compensation RL or RR"));
    }
    out.up = v.number(1) > 0.0 ? -1.0 : 1.0;
    out.clearance = v.number(6);
    out.plunge = v.feed(11);
    out.mill = v.feed(12);
    return infeedDepths(cycle, 0.0, std::fabs(v.number(1)), v.number(10), out.depths);
}

std::optional<CycleError> needsOpenLine(int cycle, const CycleContext& ctx) {
    if (!ctx.train.closed) return std::nullopt;
    return contourError(cycle, KERF_TR_NOOP("cycle {1}: the centre line must be an open "
                                            "contour, not end where it starts"));
}

// From above, over `p` at the set-up clearance.
void overPoint(CyclePath& path, const Vec2& p, const Setup& s) {
    if (path.w() > s.clearance) {
        path.rapidUv(p);
        path.rapidW(s.clearance);
    } else {
        path.rapidW(s.clearance);
        path.rapidUv(p);
    }
}

// Half a circle from the tool to `to` whose direction is `tangent` at `to` (or at its start):
// the tangential approach to a wall and the departure from it.
void halfTurn(CyclePath& path, const Vec2& to, const Vec2& tangent, bool tangentAtStart,
              const Feed& feed) {
    const Vec2 from = path.uv();
    if ((to - from).norm() < 1e-9) return;
    const Vec2 middle = (from + to) / 2.0;
    const Vec2 radial = tangentAtStart ? Vec2(from - middle) : Vec2(to - middle);
    const Vec2 counterClockwise{-radial.y(), radial.x()};
    const double sweep =
        counterClockwise.dot(tangent) >= 0.0 ? std::numbers::pi : -std::numbers::pi;
    path.arc({to.x(), to.y(), path.w()}, middle, sweep, feed);
}

// The closed path at `distance` around an open chain: along the offset on `firstSide` (+1 left),
// half a circle about the end, back along the other side, half a circle about the start. Empty
// when the offsets do not exist.
Chain pathAround(const Chain& chain, double distance, int firstSide) {
    if (distance < 1e-9) {
        Chain out = chain;
        const Chain back = reversedChain(chain);
        out.insert(out.end(), back.begin(), back.end());
        return out;
    }
    auto first = offsetOpenChain(chain, firstSide * distance);
    auto second = offsetOpenChain(chain, -firstSide * distance);
    if (!first || !second || first->empty() || second->empty()) return {};
    // From the first side round the end to the second: a left side turns clockwise.
    const double cap = -firstSide * std::numbers::pi;
    Chain out = *first;
    out.push_back(PlanarSegment::arc(first->back().end, chain.back().end, cap));
    out.back().end = second->back().end;
    const Chain back = reversedChain(*second);
    out.insert(out.end(), back.begin(), back.end());
    out.push_back(PlanarSegment::arc(second->front().start, chain.front().start, cap));
    out.back().end = first->front().start;
    return out;
}

// Cycle 27: the contour beside itself by the tool radius plus Q3, the tool radial.
std::optional<CycleError> expand27(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    Setup s;
    if (auto e = readSetup(27, v, ctx, false, s)) return e;
    if (s.depths.empty()) return std::nullopt;
    const double distance = ctx.tool.radius + v.number(3);
    if (ctx.train.side != 0 && distance < 0.0) return pocket::toolTooLarge(27);
    const Chain chain = trainCentrePath(ctx.train, ctx.train.side, distance);
    if (chain.empty()) return pocket::toolTooLarge(27);
    const Vec2 plungeAt = chain.front().start;
    for (double depth : s.depths) {
        overPoint(path, plungeAt, s);
        path.moveW(s.at(depth), s.plunge);
        followChain(path, chain, s.mill);
        path.rapidW(s.clearance);
    }
    return std::nullopt;
}

// Cycle 28: the slot about its centre line, both walls and the round ends, from the plunging
// point on the centre line; RL mills the right wall forward (climb with M3), RR the left one.
std::optional<CycleError> expand28(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    Setup s;
    if (auto e = readSetup(28, v, ctx, true, s)) return e;
    if (auto e = needsOpenLine(28, ctx)) return e;
    if (s.depths.empty()) return std::nullopt;
    // Q3 is left on each wall: the slot gets narrower by twice Q3 (spec §7, cycle 28).
    const double wall = std::fabs(v.number(20)) / 2.0 - v.number(3) - ctx.tool.radius;
    if (wall < -1e-9) return pocket::toolTooLarge(28);
    const Chain loop = pathAround(ctx.train.segments, std::max(wall, 0.0), -ctx.train.side);
    if (loop.empty()) return pocket::toolTooLarge(28);
    const Vec2 centre = ctx.train.segments.front().start;
    auto pass = [&](double depth) {
        path.moveW(s.at(depth), s.plunge);
        halfTurn(path, loop.front().start, loop.front().startTangent(), false, s.mill);
        followChain(path, loop, s.mill);
        halfTurn(path, centre, loop.back().endTangent(), true, s.mill);
    };
    overPoint(path, centre, s);
    for (double depth : s.depths)
        pass(depth);
    // Q21: once more round the slot at the full depth, to the tolerance.
    if (v.number(21) > 0.0) pass(s.depths.back());
    path.rapidW(s.clearance);
    return std::nullopt;
}

// Cycle 29: round the ridge on its centre line, starting beside its first point by half the
// ridge width plus the tool diameter; RL on its left (climb with M3), RR on its right.
std::optional<CycleError> expand29(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    Setup s;
    if (auto e = readSetup(29, v, ctx, true, s)) return e;
    if (auto e = needsOpenLine(29, ctx)) return e;
    if (s.depths.empty()) return std::nullopt;
    const double half = std::fabs(v.number(20)) / 2.0;
    const double wall = half + v.number(3) + ctx.tool.radius;
    if (wall < 1e-9) return pocket::toolTooLarge(29);
    const Chain loop = pathAround(ctx.train.segments, wall, ctx.train.side);
    if (loop.empty()) return pocket::toolTooLarge(29);
    const Vec2 centre = ctx.train.segments.front().start;
    const Vec2 side = (loop.front().start - centre).normalized();
    const Vec2 start = centre + (half + 2.0 * ctx.tool.radius) * side;
    overPoint(path, start, s);
    for (double depth : s.depths) {
        path.moveW(s.at(depth), s.plunge);
        halfTurn(path, loop.front().start, loop.front().startTangent(), false, s.mill);
        followChain(path, loop, s.mill);
        halfTurn(path, start, loop.back().endTangent(), true, s.mill);
    }
    path.rapidW(s.clearance);
    return std::nullopt;
}

// Cycle 39: beside the contour to produce by the tool radius plus Q3, from a start the tool
// diameter beside its first point, tangentially on and off.
std::optional<CycleError> expand39(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    Setup s;
    if (auto e = readSetup(39, v, ctx, true, s)) return e;
    if (s.depths.empty()) return std::nullopt;
    const double distance = ctx.tool.radius + v.number(3);
    if (distance < 1e-9) return pocket::toolTooLarge(39);
    const Chain chain = trainCentrePath(ctx.train, ctx.train.side, distance);
    if (chain.empty()) return pocket::toolTooLarge(39);
    auto beside = [&](const Vec2& programmed, const Vec2& onPath) -> Vec2 {
        return programmed + 2.0 * ctx.tool.radius * (onPath - programmed).normalized();
    };
    const Vec2 start = beside(ctx.train.segments.front().start, chain.front().start);
    const Vec2 end =
        ctx.train.closed ? start : beside(ctx.train.segments.back().end, chain.back().end);
    for (double depth : s.depths) {
        overPoint(path, start, s);
        path.moveW(s.at(depth), s.plunge);
        halfTurn(path, chain.front().start, chain.front().startTangent(), false, s.mill);
        followChain(path, chain, s.mill);
        halfTurn(path, end, chain.back().endTangent(), true, s.mill);
        path.rapidW(s.clearance);
    }
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle27{.number = 27,
                               .name = KERF_TR_NOOP("CYLINDER SURFACE"),
                               .group = CycleGroup::CylinderSurface,
                               .parameters = kParameters27,
                               .expand = expand27};
const CycleDescriptor kCycle28{.number = 28,
                               .name = KERF_TR_NOOP("CYLINDER SURFACE SLOT"),
                               .group = CycleGroup::CylinderSurface,
                               .parameters = kParameters28,
                               .expand = expand28};
const CycleDescriptor kCycle29{.number = 29,
                               .name = KERF_TR_NOOP("CYLINDER SURFACE RIDGE"),
                               .group = CycleGroup::CylinderSurface,
                               .parameters = kParameters29,
                               .expand = expand29};
const CycleDescriptor kCycle39{.number = 39,
                               .name = KERF_TR_NOOP("CYLINDER SURFACE CONTOUR"),
                               .group = CycleGroup::CylinderSurface,
                               .parameters = kParameters27,
                               .expand = expand39};

}  // namespace kerf::cycles
