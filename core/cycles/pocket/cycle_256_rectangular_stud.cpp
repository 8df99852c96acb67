// Cycle 256 RECTANGULAR STUD (spec §4): the stud Q218 x Q219 with corner radius (Q220 > 0) or
// chamfer (Q220 < 0) from the blank Q424 x Q425, placed by Q367 and turned by Q224 about the
// tool position at the call; machined by stud_machining from the start point beside the blank
// on the +u side (Q437 = 0) or beside one of its corners (Q437 1-4).
#include <cmath>
#include <numbers>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/pocket_parameters.h"
#include "core/cycles/pocket/stud_machining.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor kParameters[] = {
    kFirstSide,
    {.q = 424,
     .description = KERF_TR_NOOP("Workpiece blank side length 1"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 100.0},
    kSecondSide,
    {.q = 425,
     .description = KERF_TR_NOOP("Workpiece blank side length 2"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 80.0},
    {.q = 220,
     .description = KERF_TR_NOOP("Corner radius (+) or chamfer (-)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    kSideAllowance,
    kRotation,
    kPosition,
    kMillingFeed,
    common::kClimbOrUpCut,
    common::kDepth,
    kPlungingDepth,
    kStudPlungeFeed,
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
    {.q = 437,
     .description = KERF_TR_NOOP("Approach position (0 right of the stud, 1-4 corners)"),
     .min = 0.0,
     .max = 4.0,
     .defaultValue = 0.0,
     .integer = true},
    common::addedLater(kOperation),
    common::addedLater(kFloorAllowance),
    common::addedLater(kFinishingInfeed),
    common::addedLater(kFinishingFeed),
};

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
    if (auto e = readSetup(256, v, ctx, setup)) return e;
    setup.plunge = Plunge::Vertical;  // beside the blank
    const double length = v.number(218);
    const double width = v.number(219);
    const double blankLength = v.number(424);
    const double blankWidth = v.number(425);
    if (blankLength < length || blankWidth < width) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the workpiece blank is smaller than the "
                                       "finished part"),
                          {"256"}};
    }
    StudShape shape;
    shape.stud = roundedRectangle(length, width, v.number(220));
    const auto withAllowance = offsetClosed(shape.stud, setup.sideAllowance);
    if (!withAllowance) return toolTooLarge(256);
    // The blank's corner is the farthest material: every pass set reaches it.
    shape.margin = withAllowance->distanceTo({blankLength / 2.0, blankWidth / 2.0});
    // Q437 1-4: beside the lower-left, lower-right, upper-right or upper-left corner of the blank,
    // the tool's edge 2 mm from both of its sides.
    if (const int corner = v.integer(437); corner != 0) {
        const double beside = setup.tool.radius + kBesideBlankMm;
        const double su = corner == 1 || corner == 4 ? -1.0 : 1.0;
        const double sv = corner <= 2 ? -1.0 : 1.0;
        shape.startCorner =
            Vec2(su * (blankLength / 2.0 + beside), sv * (blankWidth / 2.0 + beside));
    }
    Placement place;
    place.angleRad = v.number(224) * std::numbers::pi / 180.0;
    place.origin = path.uv();
    place.origin = place.point(centreOffset(v.integer(367), length, width));
    shape.placement = place;
    return machineStud(setup, shape, path);
}

}  // namespace

const CycleDescriptor kCycle256{.number = 256,
                                .name = KERF_TR_NOOP("RECTANGULAR STUD"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
