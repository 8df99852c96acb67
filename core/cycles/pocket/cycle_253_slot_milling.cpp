// Cycle 253 SLOT MILLING (spec §4): the slot Q218 x Q219 (ends rounded with half the width),
// placed by Q367 and turned by Q374 about the tool position at the call; plunged at the centre of
// the left arc (Q366 1 and 2 both reciprocate along the slot) and machined by pocket_machining.
// A slot as wide as the tool is one stroke along its centre line (roughing only).
#include <numbers>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/pocket_machining.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor kParameters[] = {
    kOperation,
    {.q = 218,
     .description = KERF_TR_NOOP("Slot length"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 80.0},
    {.q = 219,
     .description = KERF_TR_NOOP("Slot width"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 12.0},
    kSideAllowance,
    {.q = 374,
     .description = KERF_TR_NOOP("Angle of rotation about the starting point"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 0.0},
    {.q = 367,
     .description = KERF_TR_NOOP("Slot position (0 centre, 1 left end, 2 centre of the left "
                                 "arc, 3 centre of the right arc, 4 right end)"),
     .min = 0.0,
     .max = 4.0,
     .defaultValue = 0.0,
     .integer = true},
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
    kPlunge,
    kFinishingFeed,
    common::addedLater(kFeedReference),  // added in -02
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    MillingSetup setup;
    if (auto e = readSetup(253, v, ctx, setup)) return e;
    if (setup.plunge != Plunge::Vertical) setup.plunge = Plunge::Reciprocating;
    const double length = v.number(218);
    const double width = v.number(219);
    if (width > length) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the slot width Q219 is larger than its "
                                       "length Q218"),
                          {"253"}};
    }
    PocketShape shape = roundedPocket(length, width, width / 2.0);
    shape.plungeAtCoreStart = true;
    const double arcCentre = (length - width) / 2.0;
    const double offsets[] = {0.0, length / 2.0, arcCentre, -arcCentre, -length / 2.0};
    Placement place;
    place.angleRad = v.number(374) * std::numbers::pi / 180.0;
    place.origin = path.uv();
    place.origin = place.point({offsets[v.integer(367)], 0.0});
    shape.placement = place;
    return machinePocket(setup, shape, path);
}

}  // namespace

const CycleDescriptor kCycle253{.number = 253,
                                .name = KERF_TR_NOOP("SLOT MILLING"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
