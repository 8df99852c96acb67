// Cycle 252 CIRCULAR POCKET (spec §4): the circle Q223 about the tool position at the call,
// machined by pocket_machining (a rounded square whose corner radius is half its side).
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/pocket_machining.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor kParameters[] = {
    kOperation,
    {.q = 223,
     .description = KERF_TR_NOOP("Circle diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 60.0},
    kSideAllowance,
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
    {.q = 370,
     .description = KERF_TR_NOOP("Maximum path overlap factor"),
     .unit = Unit::Factor,
     .min = 0.1,
     .max = 1.9999,
     .defaultValue = 1.0,
     .predef = true},
    {.q = 366,
     .description = KERF_TR_NOOP("Plunging strategy (0 vertical, 1 helical)"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 1.0,
     .predef = true,
     .integer = true},
    kFinishingFeed,
    common::addedLater(kFeedReference),  // added in -02
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    MillingSetup setup;
    if (auto e = readSetup(252, v, ctx, setup)) return e;
    const double angle = ctx.tool.plungeAngleDeg;
    if (setup.plunge == Plunge::Vertical && angle != 0.0 && angle != 90.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1}: vertical plunging (Q366 = 0) needs a tool "
                                       "whose ANGLE is 0 or 90"),
                          {"252"}};
    }
    PocketShape shape = roundedPocket(v.number(223), v.number(223), v.number(223) / 2.0);
    shape.placement.origin = path.uv();
    return machinePocket(setup, shape, path);
}

}  // namespace

const CycleDescriptor kCycle252{.number = 252,
                                .name = KERF_TR_NOOP("CIRCULAR POCKET"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
