// Cycle 22 ROUGH-OUT (spec §6): the area of cycle 14 cleared contour-parallel from the inside
// out at each plunging depth, islands milled around; with Q18 only what a coarser tool left.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/cycles/contour/sl_end_position.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/contour/train_rest.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/milling_setup.h"

namespace kerf::cycles {

namespace {

using namespace contour;

constexpr ParameterDescriptor kParameters[] = {
    kPlungingDepth,
    kPlungeFeed,
    kMillingFeed,
    {.q = 18,
     .description = KERF_TR_NOOP("Coarse roughing tool number (0: none)"),
     .min = 0.0,
     .max = 99999.0,
     .defaultValue = 0.0},
    {.q = 19,
     .description = KERF_TR_NOOP("Feed rate for reciprocation"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 0.0,
     .keywords = kFeedWords},
    common::addedLater(kRetractionFeed),
    common::addedLater({.q = 401,
                        .description = KERF_TR_NOOP("Feed rate factor in %"),
                        .unit = Unit::Percent,
                        .min = 0.0001,
                        .max = 100.0,
                        .defaultValue = 100.0}),
    common::addedLater({.q = 404,
                        .description = KERF_TR_NOOP("Fine roughing strategy (0 along the contour, "
                                                    "1 retract between areas)"),
                        .min = 0.0,
                        .max = 1.0,
                        .defaultValue = 0.0,
                        .integer = true}),
};

// Q19 with the tool's ANGLE (spec): 0 vertical at Q11; ANGLE 90 vertical at Q19; no ANGLE is an
// error; a smaller ANGLE plunges on a helix at that angle at Q19 (`helixTan` = tan ANGLE).
std::optional<CycleError> plungeFeed(const CycleValues& v, const CycleContext& ctx, Feed& out,
                                     double& helixTan) {
    out = v.feed(11);
    helixTan = 0.0;
    if (v.number(19) <= 0.0) return std::nullopt;
    const double angle = ctx.tool.plungeAngleDeg;
    if (angle <= 0.0) {
        return contourError(22, KERF_TR_NOOP("cycle {1}: the feed rate for reciprocation Q19 "
                                             "needs the plunge angle ANGLE of the tool"));
    }
    if (angle < 90.0 - 1e-9) helixTan = std::tan(angle * std::numbers::pi / 180.0);
    out = v.feed(19);
    return std::nullopt;
}

// With a coarse roughing tool: only where it could not reach (the rest material, which does not
// know the coarse tool's DR), widened by the tool radius so the tool reaches all of it.
Region restRegion(const ToolInfo& coarse, const CycleContext& ctx, const ContourArea& area,
                  size_t level, const ContourData& d, const Region& region) {
    const Region coarseCentre = toolCentreRegion(area, coarse.radius + d.sideAllowance, level);
    const Region cleared = offsetRegion(coarseCentre, coarse.radius);
    const Region rest = subtract(offsetRegion(area.levels[level].area, -d.sideAllowance), cleared);
    return rest.empty() ? Region{} : intersect(region, offsetRegion(rest, ctx.tool.radius));
}

// The roughing depths: Q10 steps to the deepest floor less Q4, and each shallower level's floor
// less Q4 (a contour formula with DEPTH), so that every floor keeps its allowance.
std::optional<CycleError> roughingDepths(const CycleValues& v, const ContourArea& area,
                                         const ContourData& d, std::vector<double>& out) {
    if (auto e = infeedDepths(22, 0.0, area.deepest() - d.floorAllowance, v.number(10), out))
        return e;
    for (size_t k = 0; k + 1 < area.levels.size(); ++k) {
        const double floor = area.levels[k].bottom - d.floorAllowance;
        if (floor > 1e-9) out.push_back(floor);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end(), [](double a, double b) { return b - a < 1e-9; }),
              out.end());
    return std::nullopt;
}

// Q404 = 1: the tool lifts between the separate rest areas (each outer boundary of the rest
// region with its holes): the first pass in each area is reached from above.
void liftBetweenAreas(std::vector<ClearingPass>& passes, const Region& region) {
    const std::vector<size_t> areas = areasOfPasses(passes, region);
    for (size_t i = 1; i < passes.size(); ++i) {
        if (areas[i] != areas[i - 1]) passes[i].straightLink = false;
    }
}

// A plunge of at most this many helix turns: an ANGLE near 0 on a small tool would make millions.
constexpr double kMaxHelixTurns = 10000.0;

// Every helix from Q6 above the depth before down to its depth stays within kMaxHelixTurns.
template <typename Plan, typename Plans>
std::optional<CycleError> checkHelixTurns(const std::vector<double>& depths,
                                          const ContourArea& area, const ContourData& d,
                                          double helixTan, Plan& plan, Plans& plans) {
    if (helixTan <= 0.0) return std::nullopt;
    double previous = 0.0;
    for (double depth : depths) {
        const size_t level = levelAt(area, depth + d.floorAllowance);
        if (auto e = plan(level)) return e;
        const double drop = depth - previous + d.setUpClearance;
        for (const ClearingPass& pass : *plans[level]) {
            if (reciprocatingStrokes(pass, drop, helixTan) > kMaxHelixTurns)
                return tooManyMoves(22);
            if (pass.helixRadius <= 0.0) continue;
            const double pitch = 2.0 * std::numbers::pi * pass.helixRadius * helixTan;
            if (drop > kMaxHelixTurns * pitch) return tooManyMoves(22);
        }
        if (!plans[level]->empty()) previous = depth;
    }
    return std::nullopt;
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    ContourData d;
    if (auto e = readContourData(22, ctx, d)) return e;
    ContourArea area;
    if (auto e = combineContours(22, ctx, d, area)) return e;
    if (area.islandsOnly) {
        return contourError(22, KERF_TR_NOOP("cycle {1} needs a pocket among the contours of "
                                             "cycle 14"));
    }
    const double radius = ctx.tool.radius;
    if (radius <= 0.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1} needs a tool with a radius greater than 0"),
                          {"22"}};
    }
    Feed plunge;
    ClearingOptions options;
    if (auto e = plungeFeed(v, ctx, plunge, options.helixTan)) return e;
    options.climb = d.climb;
    // Q401: absent (an older block read without it) is 100 %.
    if (v.number(401) > 0.0) options.fullWidthFactor = v.number(401) / 100.0;
    const Feed mill = v.feed(12);
    const Feed retract = v.feedOr(208, 12);
    // The clearing of each level, planned when a depth first needs it.
    ToolInfo coarse;
    if (v.number(18) > 0.0) {
        if (auto e = coarseTool(22, v, ctx, coarse)) return e;
    }
    // Q404 decides only for a fine tool of at least half the coarse one's radius (spec); a
    // smaller one always lifts between the rest areas [interp].
    const bool alongContour = v.number(404) <= 0.5 && radius >= coarse.radius / 2.0 - 1e-9;
    std::vector<std::optional<std::vector<ClearingPass>>> plans(area.levels.size());
    auto plan = [&](size_t level) -> std::optional<CycleError> {
        if (plans[level]) return std::nullopt;
        const Region room = toolCentreRegion(area, radius + d.sideAllowance, level);
        if (room.empty() && level == 0) return pocket::toolTooLarge(22);
        Region region = room;
        if (v.number(18) > 0.0 && !region.empty())
            region = restRegion(coarse, ctx, area, level, d, region);
        std::vector<ClearingPass> passes;
        if (!region.empty()) {
            if (auto e = planClearing(22, region, d.overlap * radius, d.climb, planningStart(ctx),
                                      passes, ctx.clearingCache))
                return e;
            // Q404 between the rest areas: 1 lifts, 0 runs along the contour at the depth.
            if (v.number(18) > 0.0 && !alongContour) liftBetweenAreas(passes, region);
            if (v.number(18) > 0.0 && alongContour) linkAlongContour(passes, room, region);
            // Where no helix fits (a slot), reciprocating over LCUTS / tan(ANGLE) (spec).
            const double strokes = options.helixTan > 0.0 && ctx.tool.cuttingLength > 0.0
                                       ? ctx.tool.cuttingLength / options.helixTan
                                       : 0.0;
            if (options.helixTan > 0.0 && !placeHelices(passes, room, radius, strokes)) {
                return CycleError{"cycle-plunge",
                                  KERF_TR_NOOP("cycle {1}: no room for the helical plunge, and "
                                               "the reciprocating plunge needs the tool's LCUTS "
                                               "(pre-drill with cycle 21 or use a centre-cutting "
                                               "tool)"),
                                  {"22"}};
            }
        }
        plans[level] = std::move(passes);
        return std::nullopt;
    };
    if (auto e = plan(0)) return e;
    std::vector<double> depths;
    if (auto e = roughingDepths(v, area, d, depths)) return e;
    if (depths.empty()) return std::nullopt;
    if (auto e = checkHelixTurns(depths, area, d, options.helixTan, plan, plans)) return e;

    bool started = false;
    double previous = 0.0;
    for (double depth : depths) {
        const size_t level = levelAt(area, depth + d.floorAllowance);
        if (auto e = plan(level)) return e;
        if (plans[level]->empty()) continue;
        if (!started && (path.w() - d.clearanceHeight) * d.up < 0.0) path.rapidW(d.clearanceHeight);
        started = true;
        runClearing(path, *plans[level], d, d.at(depth), d.at(previous) + d.up * d.setUpClearance,
                    mill, plunge, options);
        previous = depth;
    }
    if (started) finishSlCycle(path, ctx, d.clearanceHeight, d.up, retract);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle22{.number = 22,
                               .name = KERF_TR_NOOP("ROUGH-OUT"),
                               .group = CycleGroup::Contours,
                               .parameters = kParameters,
                               .expand = expand};

}  // namespace kerf::cycles
