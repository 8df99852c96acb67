// Cycle 24 SIDE FINISHING (spec §6): every boundary of the machined area finished on its own, at
// the plunging depths, approached and left on quarter arcs from the free side.
#include <algorithm>

#include "core/cycles/contour/sl_end_position.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/milling_setup.h"

namespace kerf::cycles {

namespace {

using namespace contour;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 9,
     .description = KERF_TR_NOOP("Direction of rotation (+1 climb, -1 up-cut)"),
     .min = -1.0,
     .max = 1.0,
     .defaultValue = 1.0,
     .integer = true},
    kPlungingDepth,
    kPlungeFeed,
    kMillingFeed,
    {.q = 14,
     .description = KERF_TR_NOOP("Finishing allowance for the side"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
};

// Radius of the approach arc: from where roughing left no material (Q3 - Q14 from the finished
// wall) if the region has room for it there, else smaller; 0: straight down onto the path.
double approachRadius(const Region& region, const ClosedContour& ring, const Vec2& inward,
                      double wanted) {
    for (double r = wanted; r > 1e-3; r /= 2.0) {
        const Vec2 start = pocket::approachStart(ring, inward, r);
        const Vec2 centre = ring.segments.front().start + r * inward;
        bool room = region.contains(start) && region.contains(centre);
        for (const ClosedContour& c : region.boundaries)
            room = room && c.distanceTo(centre) >= r - 1e-9;
        if (room) return r;
    }
    return 0.0;
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    ContourData d;
    if (auto e = readContourData(24, ctx, d)) return e;
    ContourArea area;
    if (auto e = combineContours(24, ctx, d, area)) return e;
    const double radius = ctx.tool.radius;
    const double allowance = v.number(14);
    // Spec: Q14 + R(finishing) < Q3 + R(roughing), R(roughing) = 0 without cycle 22 before.
    if (radius <= 0.0 || allowance + radius >= d.sideAllowance + ctx.roughingRadius) {
        return pocket::toolTooLarge(24);
    }
    const Region firstLevel = toolCentreRegion(area, radius + allowance);
    if (firstLevel.empty()) return pocket::toolTooLarge(24);
    bool climb = v.integer(9) >= 0;
    if (ctx.mirroredMain != ctx.mirroredSecondary) climb = !climb;
    const Feed plunge = v.feed(11);
    const Feed mill = v.feed(12);

    if ((path.w() - d.clearanceHeight) * d.up < 0.0) path.rapidW(d.clearanceHeight);
    // Each level's walls from the level above down to its bottom (one level without DEPTHs).
    double top = 0.0;
    for (size_t level = 0; level < area.levels.size(); ++level) {
        const Region region =
            level == 0 ? firstLevel : toolCentreRegion(area, radius + allowance, level);
        std::vector<double> depths;
        if (auto e = infeedDepths(24, top, area.levels[level].bottom, v.number(10), depths))
            return e;
        for (const ClosedContour& boundary : region.boundaries) {
            const ClosedContour ring = climb ? boundary : boundary.reversed();
            // The region, where the tool comes from, lies left of its own boundaries.
            const Vec2 t = ring.segments.front().startTangent();
            const Vec2 inward = climb ? Vec2(-t.y(), t.x()) : Vec2(t.y(), -t.x());
            const double arcRadius = approachRadius(
                region, ring, inward, std::max(d.sideAllowance - allowance, 0.0) + radius / 2.0);
            const Vec2 entry = pocket::approachStart(ring, inward, arcRadius);
            double previous = top;
            for (double depth : depths) {
                if ((path.w() - d.aboveSurface()) * d.up < 0.0) path.rapidW(d.aboveSurface());
                path.rapidUv(entry);
                path.rapidW(d.at(previous) + d.up * d.setUpClearance);
                path.moveW(d.at(depth), plunge);
                if (arcRadius > 0.0) pocket::approachArc(path, ring, inward, arcRadius, mill);
                followPath(path, ring, mill);
                if (arcRadius > 0.0) pocket::departureArc(path, ring, inward, arcRadius, mill);
                previous = depth;
            }
        }
        top = area.levels[level].bottom;
    }
    finishSlCycle(path, ctx, d.clearanceHeight, d.up, Feed::rapid());
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle24{.number = 24,
                               .name = KERF_TR_NOOP("SIDE FINISHING"),
                               .group = CycleGroup::Contours,
                               .parameters = kParameters,
                               .expand = expand};

}  // namespace kerf::cycles
