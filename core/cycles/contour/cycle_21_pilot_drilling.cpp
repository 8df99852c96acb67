// Cycle 21 PILOT DRILLING (spec §6): holes where cycle 22 will plunge with the rough-out tool
// Q13, in infeeds of Q10 down to the depth less the floor allowance.
#include <algorithm>
#include <cmath>

#include "core/cycles/contour/sl_end_position.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/milling_setup.h"

namespace kerf::cycles {

namespace {

using namespace contour;

constexpr ParameterDescriptor kParameters[] = {
    kPlungingDepth,
    kPlungeFeed,
    {.q = 13,
     .description = KERF_TR_NOOP("Rough-out tool number (0: the tool in the spindle)"),
     .min = 0.0,
     .max = 32767.9,
     .defaultValue = 0.0},
};

// Spec: the advanced stop distance t is 0.6 mm up to 30 mm of hole depth, then depth / 50,
// at most 7 mm.
double advancedStop(double holeDepth) {
    return holeDepth <= 30.0 ? 0.6 : std::min(holeDepth / 50.0, 7.0);
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    ContourData d;
    if (auto e = readContourData(21, ctx, d)) return e;
    ContourArea area;
    if (auto e = combineContours(21, ctx, d, area)) return e;
    if (area.islandsOnly) {
        return contourError(21, KERF_TR_NOOP("cycle {1} needs a pocket among the contours of "
                                             "cycle 14"));
    }
    const int number = static_cast<int>(v.number(13));
    std::optional<ToolInfo> rougher = ctx.tool;
    if (number != 0) rougher = ctx.toolByNumber ? ctx.toolByNumber(number) : std::nullopt;
    if (!rougher) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1}: tool {2} ({3}) is not in the tool table"),
                          {"21", std::to_string(number), "Q13"}};
    }
    if (rougher->radius <= 0.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1} needs a tool with a radius greater than 0"),
                          {"21"}};
    }
    // The plunging points of cycle 22 with that tool: where its clearing plunges.
    const Region region = toolCentreRegion(area, rougher->radius + d.sideAllowance);
    if (region.empty()) return pocket::toolTooLarge(21);
    std::vector<ClearingPass> passes;
    if (auto e = planClearing(21, region, d.overlap * rougher->radius, d.climb, planningStart(ctx),
                              passes, ctx.clearingCache))
        return e;
    // A hole goes down to the deepest level whose tool-centre region holds it (contour formula
    // with DEPTH), less the floor allowance.
    std::vector<Region> levelRegions{region};
    for (size_t k = 1; k < area.levels.size(); ++k)
        levelRegions.push_back(toolCentreRegion(area, rougher->radius + d.sideAllowance, k));
    const Feed feed = v.feed(11);

    bool started = false;
    for (const ClearingPass& pass : passes) {
        if (pass.straightLink) continue;
        const Vec2 at = pass.path.segments.front().start;
        size_t level = 0;
        while (level + 1 < levelRegions.size() && levelRegions[level + 1].contains(at))
            ++level;
        const double holeDepth = area.levels[level].bottom - d.floorAllowance;
        std::vector<double> depths;
        if (auto e = infeedDepths(21, 0.0, holeDepth, v.number(10), depths)) return e;
        if (depths.empty()) continue;
        const double t = advancedStop(holeDepth);
        if (!started && (path.w() - d.clearanceHeight) * d.up < 0.0) path.rapidW(d.clearanceHeight);
        started = true;
        if ((path.w() - d.aboveSurface()) * d.up < 0.0) path.rapidW(d.aboveSurface());
        path.rapidUv(at);
        path.rapidW(d.aboveSurface());
        for (size_t i = 0; i < depths.size(); ++i) {
            if (i > 0) {
                path.rapidW(d.aboveSurface());
                path.rapidW(d.at(depths[i - 1] - t));
            }
            path.moveW(d.at(depths[i]), feed);
        }
        path.rapidW(d.aboveSurface());
    }
    if (!started) return std::nullopt;
    finishSlCycle(path, ctx, d.clearanceHeight, d.up, Feed::rapid());
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle21{.number = 21,
                               .name = KERF_TR_NOOP("PILOT DRILLING"),
                               .group = CycleGroup::Contours,
                               .parameters = kParameters,
                               .expand = expand};

}  // namespace kerf::cycles
