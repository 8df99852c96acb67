// Cycle 257 CIRCULAR STUD (spec §4): the stud Q223 from the blank Q222 about the tool position at
// the call, approached at the polar angle Q376 (-1: automatic, taken as 0); machined by
// stud_machining with concentric passes.
#include <algorithm>
#include <numbers>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/pocket_parameters.h"
#include "core/cycles/pocket/stud_machining.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 223,
     .description = KERF_TR_NOOP("Finished part diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 60.0},
    {.q = 222,
     .description = KERF_TR_NOOP("Workpiece blank diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 80.0},
    kSideAllowance,
    kMillingFeed,
    common::kClimbOrUpCut,
    common::kDepth,
    kPlungingDepth,
    kStudPlungeFeed,
    common::kSetUpClearance,
    common::kSurface,
    common::kSecondClearance,
    kOverlap,
    {.q = 376,
     .description = KERF_TR_NOOP("Starting angle"),
     .unit = Unit::Degrees,
     .min = -1.0,
     .max = 359.0,
     .defaultValue = 0.0},
    common::addedLater(kOperation),
    common::addedLater(kFloorAllowance),
    common::addedLater(kFinishingInfeed),
    common::addedLater(kFinishingFeed),
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    MillingSetup setup;
    if (auto e = readSetup(257, v, ctx, setup)) return e;
    setup.plunge = Plunge::Vertical;  // beside the blank
    const double finished = v.number(223);
    const double blank = v.number(222);
    if (blank < finished) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the workpiece blank is smaller than the "
                                       "finished part"),
                          {"257"}};
    }
    StudShape shape;
    shape.stud = circleContour(finished / 2.0);
    shape.margin = (blank - finished) / 2.0 - setup.sideAllowance;
    shape.placement.origin = path.uv();
    shape.placement.angleRad = std::max(0.0, v.number(376)) * std::numbers::pi / 180.0;
    return machineStud(setup, shape, path);
}

}  // namespace

const CycleDescriptor kCycle257{.number = 257,
                                .name = KERF_TR_NOOP("CIRCULAR STUD"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
