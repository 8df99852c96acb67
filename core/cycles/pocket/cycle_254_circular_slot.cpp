// Cycle 254 CIRCULAR SLOT (spec §4): the slot of width Q219 along the pitch circle Q375 from the
// starting angle Q376 over Q248, repeated Q377 times turned by Q378 about the pitch-circle
// centre. Q367 says what the tool position at the call is: 0 nothing (centre Q216/Q217), 1 the
// centre of the slot's start arc, 2 the middle of its centre line, 3 the centre of its end arc;
// Q376 is the polar angle of that point. Plunged at the centre of the start arc (Q366 1 and 2 both
// reciprocate along the pitch arc) and machined by pocket_machining; the cycle ends in the tool
// axis only.
#include <cmath>
#include <numbers>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pocket/pocket_machining.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr int kMaxRepetitions = 99999;

constexpr ParameterDescriptor kParameters[] = {
    kOperation,
    {.q = 219,
     .description = KERF_TR_NOOP("Slot width"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 12.0},
    kSideAllowance,
    {.q = 375,
     .description = KERF_TR_NOOP("Pitch circle diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 80.0},
    {.q = 367,
     .description = KERF_TR_NOOP("Reference of the slot position (0 centre Q216/Q217, 1 start "
                                 "arc, 2 middle, 3 end arc at the tool position)"),
     .min = 0.0,
     .max = 3.0,
     .defaultValue = 0.0,
     .integer = true},
    {.q = 216,
     .description = KERF_TR_NOOP("Centre in the 1st axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 217,
     .description = KERF_TR_NOOP("Centre in the 2nd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 376,
     .description = KERF_TR_NOOP("Starting angle"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 0.0},
    {.q = 248,
     .description = KERF_TR_NOOP("Angular length of the slot"),
     .unit = Unit::Degrees,
     .min = 0.0,
     .max = 360.0,
     .defaultValue = 90.0},
    {.q = 378,
     .description = KERF_TR_NOOP("Stepping angle between repetitions"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 0.0},
    {.q = 377,
     .description = KERF_TR_NOOP("Number of repetitions"),
     .unit = Unit::Count,
     .min = 1.0,
     .max = kMaxRepetitions,
     .defaultValue = 1.0,
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
    if (auto e = readSetup(254, v, ctx, setup)) return e;
    if (setup.plunge != Plunge::Vertical) setup.plunge = Plunge::Reciprocating;
    const double width = v.number(219);
    const double pitch = v.number(375) / 2.0;
    const double sweep = v.number(248) * kDegree;
    if (width >= 2.0 * pitch) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the slot width Q219 must be smaller than the "
                                       "pitch circle diameter Q375"),
                          {"254"}};
    }
    // The two ends must not meet behind the slot.
    const double gap = 2.0 * std::numbers::pi - sweep;
    if (gap < std::numbers::pi && 2.0 * pitch * std::sin(gap / 2.0) < width) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the angular length Q248 closes the slot on "
                                       "itself"),
                          {"254"}};
    }
    const double angle = v.number(376) * kDegree;
    const int reference = v.integer(367);
    const double startAngle = reference == 2   ? angle - sweep / 2.0
                              : reference == 3 ? angle - sweep
                                               : angle;
    const Vec2 direction(std::cos(angle), std::sin(angle));
    const Vec2 centre =
        reference == 0 ? Vec2(v.number(216), v.number(217)) : Vec2(path.uv() - pitch * direction);
    PocketShape shape;
    shape.contour = arcSlot(pitch, startAngle, sweep, width);
    shape.halfWidth = width / 2.0;
    shape.core = PlanarSegment::arc(pitch * Vec2(std::cos(startAngle), std::sin(startAngle)),
                                    Vec2(0.0, 0.0), sweep);
    shape.plungeAtCoreStart = true;
    shape.returnToStart = false;
    shape.convex = false;
    shape.placement.origin = centre;
    for (int k = 0; k < v.integer(377); ++k) {
        shape.placement.angleRad = k * v.number(378) * kDegree;
        if (auto e = machinePocket(setup, shape, path)) return e;
        if (path.limitReached()) return tooManyMoves(254);
    }
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle254{.number = 254,
                                .name = KERF_TR_NOOP("CIRCULAR SLOT"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
