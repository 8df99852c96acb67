// Cycle 258 POLYGON STUD (spec §4): a regular polygon of Q572 corners whose reference circle Q571
// is the inscribed (Q573 = 0) or circumscribed (1) one, its first corner at the angle Q224, corners
// rounded (Q220 > 0) or chamfered (Q220 < 0), from a round blank Q222 about the tool position at
// the call; machined by stud_machining from beside the blank. The start point lies on the normal
// of a side, so the passes start in the middle of a side.
#include <cmath>
#include <numbers>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/pocket_parameters.h"
#include "core/cycles/pocket/stud_machining.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 573,
     .description = KERF_TR_NOOP("Reference circle (0 inscribed, 1 circumscribed)"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 0.0,
     .integer = true},
    {.q = 571,
     .description = KERF_TR_NOOP("Reference circle diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 222,
     .description = KERF_TR_NOOP("Workpiece blank diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 120.0},
    {.q = 572,
     .description = KERF_TR_NOOP("Number of corners"),
     .unit = Unit::Count,
     .min = 0.0,
     .max = 30.0,
     .defaultValue = 6.0,
     .integer = true},
    {.q = 224,
     .description = KERF_TR_NOOP("Angle of the first corner"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 0.0},
    {.q = 220,
     .description = KERF_TR_NOOP("Corner radius (+) or chamfer (-)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    // Spec: a negative side allowance makes the polygon smaller (no side finishing then).
    {.q = 368,
     .description = KERF_TR_NOOP("Finishing allowance for the side"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    kMillingFeed,
    common::kClimbOrUpCut,
    common::kDepth,
    kPlungingDepth,
    kStudPlungeFeed,
    common::kSetUpClearance,
    common::kSurface,
    common::kSecondClearance,
    kOverlap,
    kOperation,
    kFloorAllowance,
    kFinishingInfeed,
    kFinishingFeed,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    MillingSetup setup;
    if (auto e = readSetup(258, v, ctx, setup)) return e;
    setup.plunge = Plunge::Vertical;  // beside the blank
    const int corners = v.integer(572);
    if (corners < 3) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: a polygon needs at least 3 corners (Q572)"),
                          {"258"}};
    }
    const double halfStep = std::numbers::pi / corners;
    const double reference = v.number(571) / 2.0;
    const double circumradius = v.integer(573) == 1 ? reference : reference / std::cos(halfStep);
    const double blankRadius = v.number(222) / 2.0;
    if (v.number(222) < v.number(571)) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the workpiece blank is smaller than the "
                                       "finished part"),
                          {"258"}};
    }
    auto polygon = regularPolygon(circumradius, corners, v.number(220));
    if (!polygon) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the corner radius or chamfer Q220 is too "
                                       "large for the sides of the polygon"),
                          {"258"}};
    }
    StudShape shape;
    shape.stud = std::move(*polygon);
    // The blank's farthest material from the stud lies opposite the middle of a side.
    shape.margin = blankRadius - circumradius * std::cos(halfStep) - setup.sideAllowance;
    shape.placement.origin = path.uv();
    shape.placement.angleRad = v.number(224) * std::numbers::pi / 180.0 - halfStep;
    return machineStud(setup, shape, path);
}

}  // namespace

const CycleDescriptor kCycle258{.number = 258,
                                .name = KERF_TR_NOOP("POLYGON STUD"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
