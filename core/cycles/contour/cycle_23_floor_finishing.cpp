// Cycle 23 FLOOR FINISHING (spec §6): the roughing's clearing once more at the floor, removing
// the floor allowance Q4; the side allowance stays.
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

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    ContourData d;
    if (auto e = readContourData(23, ctx, d)) return e;
    ContourArea area;
    if (auto e = combineContours(23, ctx, area)) return e;
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
    const Region region = toolCentreRegion(area, radius + d.sideAllowance);
    if (region.empty()) return pocket::toolTooLarge(23);
    std::vector<ClearingPass> passes;
    if (auto e = planClearing(23, region, d.overlap * radius, d.climb, planningStart(ctx), passes))
        return e;

    if ((path.w() - d.clearanceHeight) * d.up < 0.0) path.rapidW(d.clearanceHeight);
    // Down at rapid to the set-up clearance above the roughed floor, then at Q11 to the floor.
    const double roughFloor = d.at(d.depth - d.floorAllowance);
    runClearing(path, passes, d, d.at(d.depth), roughFloor + d.up * d.setUpClearance, v.feed(12),
                v.feed(11));
    path.moveW(d.clearanceHeight, v.feedOr(208, 12));
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle23{.number = 23,
                               .name = KERF_TR_NOOP("FLOOR FINISHING"),
                               .group = CycleGroup::Contours,
                               .parameters = kParameters,
                               .expand = expand};

}  // namespace kerf::cycles
