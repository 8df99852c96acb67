// Cycle 251 RECTANGULAR POCKET (spec §4): the pocket Q218 x Q219 with corner radius Q220 (0: the
// tool radius), placed by Q367 and turned by Q224 about the tool position at the call; machined
// by pocket_machining.
#include <cmath>
#include <numbers>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/pocket_machining.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor kParameters[] = {
    kOperation,
    kFirstSide,
    kSecondSide,
    {.q = 220,
     .description = KERF_TR_NOOP("Corner radius (0: tool radius)"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0},
    kSideAllowance,
    kRotation,
    kPosition,
    kMillingFeed,
    common::kClimbOrUpCut,
    common::kDepth,
    kPlungingDepth,
    kFloorAllowance,
    kPlungeFeed,
    kFinishingInfeed,
    common::kSetUpClearance,
    common::kSurface,
    common::kSecondClearance,
    kOverlap,
    kPlunge,
    kFinishingFeed,
    common::addedLater(kFeedReference),
};

// Centre of the rectangle relative to the tool position for Q367 = 0..4 (before the rotation).
Vec2 centreOffset(int position, double length, double width) {
    switch (position) {
        case 1:
            return {length / 2.0, width / 2.0};
        case 2:
            return {-length / 2.0, width / 2.0};
        case 3:
            return {-length / 2.0, -width / 2.0};
        case 4:
            return {length / 2.0, -width / 2.0};
        default:
            return {0.0, 0.0};
    }
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    MillingSetup setup;
    if (auto e = readSetup(251, v, ctx, setup)) return e;
    const double length = v.number(218);
    const double width = v.number(219);
    PocketShape shape =
        roundedPocket(length, width, v.number(220) > 0.0 ? v.number(220) : ctx.tool.radius);
    Placement place;
    place.angleRad = v.number(224) * std::numbers::pi / 180.0;
    place.origin = path.uv();
    place.origin = place.point(centreOffset(v.integer(367), length, width));
    shape.placement = place;
    return machinePocket(setup, shape, path);
}

}  // namespace

const CycleDescriptor kCycle251{.number = 251,
                                .name = KERF_TR_NOOP("RECTANGULAR POCKET"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
