// Cycle 23 FLOOR FINISHING (spec §6): the roughing's clearing once more at the floor, removing
// the floor allowance Q4; the side allowance stays.
#include "core/cycles/contour/sl_end_position.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/milling_setup.h"

namespace kerf::cycles {

namespace {

using namespace contour;

constexpr ParameterDescriptor kParameters[] = {
    kPlungeFeed,
    kMillingFeed,
    common::addedLater(kRetractionFeed),
};

// The tool-centre region over the floor of one level: where the level's area does not go deeper
// (the tool may reach over the deeper part, which is already finished lower down). `region`:
// the level's tool-centre region.
Region floorRegion(const ContourArea& area, size_t level, Region region, double radius) {
    if (level + 1 < area.levels.size() && !region.empty()) {
        const Region floor = subtract(area.levels[level].area, area.levels[level + 1].area);
        region = floor.empty() ? Region{} : intersect(region, offsetRegion(floor, radius));
    }
    return region;
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    ContourData d;
    if (auto e = readContourData(23, ctx, d)) return e;
    ContourArea area;
    if (auto e = combineContours(23, ctx, d, area)) return e;
    if (area.islandsOnly) {
        return contourError(23, KERF_TR_NOOP("cycle {1} needs a pocket among the contours of "
                                             "cycle 14"));
    }
    const double radius = ctx.tool.radius;
    if (radius <= 0.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1} needs a tool with a radius greater than 0"),
                          {"23"}};
    }
    const Region top = toolCentreRegion(area, radius + d.sideAllowance);
    if (top.empty()) return pocket::toolTooLarge(23);

    if ((path.w() - d.clearanceHeight) * d.up < 0.0) path.rapidW(d.clearanceHeight);
    // Each floor, shallowest first: down at rapid to the set-up clearance above the roughed
    // floor, then at Q11 to the floor (on the approach arc where it fits).
    for (size_t level = 0; level < area.levels.size(); ++level) {
        const Region room =
            level == 0 ? top : toolCentreRegion(area, radius + d.sideAllowance, level);
        const Region region = floorRegion(area, level, room, radius);
        if (region.empty()) continue;
        std::vector<ClearingPass> passes;
        if (auto e = planClearing(23, region, d.overlap * radius, d.climb, planningStart(ctx),
                                  passes, ctx.clearingCache))
            return e;
        // Onto the floor on a vertical quarter arc of the tool radius where it has room (spec).
        placeApproachArcs(passes, room, radius);
        const double bottom = area.levels[level].bottom;
        const double roughFloor = d.at(bottom - d.floorAllowance);
        runClearing(path, passes, d, d.at(bottom), roughFloor + d.up * d.setUpClearance, v.feed(12),
                    v.feed(11));
    }
    finishSlCycle(path, ctx, d.clearanceHeight, d.up, v.feedOr(208, 12));
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle23{.number = 23,
                               .name = KERF_TR_NOOP("FLOOR FINISHING"),
                               .group = CycleGroup::Contours,
                               .parameters = kParameters,
                               .expand = expand};

}  // namespace kerf::cycles
