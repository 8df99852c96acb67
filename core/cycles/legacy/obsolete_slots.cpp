// Obsolete cycles 210 SLOT RECIP. PLNG. and 211 CIRCULAR SLOT (docs/cycles.md, "Obsolete
// Q-parameter cycles"): roughing along the slot's centre line (a straight line or an arc of the
// pitch circle) with a reciprocating plunge down to the depth, then the walls finished as
// cycles 253 and 254 do with finishing only.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/legacy/legacy_list.h"
#include "core/cycles/pocket/milling_setup.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace legacy;
using namespace pocket;

constexpr double kDegree = std::numbers::pi / 180.0;
// As in cycles 212-215: the finishing pass runs where an allowance is left.
constexpr double kLeastAllowance = 0.001;

constexpr ParameterDescriptor kSlotLength{.q = 218,
                                          .description = KERF_TR_NOOP("Slot length"),
                                          .unit = Unit::Millimetre,
                                          .min = 0.0,
                                          .max = kLength,
                                          .defaultValue = 80.0};
constexpr ParameterDescriptor kSlotWidth{.q = 219,
                                         .description = KERF_TR_NOOP("Slot width"),
                                         .unit = Unit::Millimetre,
                                         .min = 0.0,
                                         .max = kLength,
                                         .defaultValue = 12.0};

// Q206 came with later software: programs without it plunge at the milling feed.
constexpr ParameterDescriptor kSlotPlungeFeed{
    .q = 206,
    .description = KERF_TR_NOOP("Feed rate for plunging (none: the milling feed)"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = common::kFeed,
    .defaultValue = 0.0,
    .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth,
    .optional = true};

constexpr ParameterDescriptor kSlotParameters[] = {
    common::kSetUpClearance,
    common::kDepth,
    kMillingFeed,
    kPlungingDepth,
    kOperation,
    common::kSurface,
    common::kSecondClearance,
    kCentreFirstAxis,
    kCentreSecondAxis,
    kSlotLength,
    kSlotWidth,
    kRotation,
    common::addedLater(kFinishingInfeed),
    kSlotPlungeFeed,
};
constexpr ParameterDescriptor kCircularSlotParameters[] = {
    common::kSetUpClearance,
    common::kDepth,
    kMillingFeed,
    kPlungingDepth,
    kOperation,
    common::kSurface,
    common::kSecondClearance,
    kCentreFirstAxis,
    kCentreSecondAxis,
    {.q = 244,
     .description = KERF_TR_NOOP("Pitch circle diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 80.0},
    kSlotWidth,
    {.q = 245,
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
    common::addedLater(kFinishingInfeed),
    kSlotPlungeFeed,
};

Feed plungeFeed(const CycleValues& v) {
    return v.has(206) && !v.feed(206).isZero() ? v.feed(206) : v.feed(207);
}

// Roughing: over the stroke's start at the 2nd set-up clearance, down to the set-up clearance
// and at the plunge feed to the surface, then to and fro along the stroke dropping Q202 per
// to-and-fro (Q202 / 2 per stroke) down to the depth, a stroke at the depth, back to the start.
void rough(const CycleValues& v, const HoleLevels& l, const PlanarSegment& stroke,
           CyclePath& path) {
    if ((path.w() - l.top) * l.up < 0.0) path.rapidW(l.top);
    path.rapidUv(stroke.start);
    path.rapidW(l.surface + l.up * v.number(200));
    path.moveW(l.surface, plungeFeed(v));
    reciprocateDown(path, stroke, l.at(std::fabs(v.number(201))), l.up * v.number(202) / 2.0,
                    plungeFeed(v));
}

// The modern slot cycle's values for finishing the walls only.
CycleValues finishing(const CycleDescriptor& modern, const CycleValues& v) {
    CycleValues m = defaultsOf(modern);
    for (uint16_t q : std::initializer_list<uint16_t>{200, 201, 202, 203, 204, 216, 217, 219})
        m.set(q, v.number(q));
    m.set(215, 2.0);
    m.set(368, kLeastAllowance);
    m.set(369, 0.0);
    m.set(338, v.number(338));
    m.set(351, 1.0);
    m.set(366, 0.0);
    m.set(367, 0.0);
    m.setFeed(206, plungeFeed(v));
    m.setFeed(207, v.feed(207));
    m.setFeed(385, v.feed(207));
    return m;
}

std::optional<CycleError> checkSlot(int number, const CycleValues& v, const CycleContext& ctx) {
    if (auto e = checkDepthSign(number, 201, v.number(201), ctx)) return e;
    if (ctx.tool.radius <= 0.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1} needs a tool with a radius greater than 0"),
                          {std::to_string(number)}};
    }
    if (2.0 * ctx.tool.radius > v.number(219) + 1e-9) return toolTooLarge(number);
    return std::nullopt;
}

std::optional<CycleError> expand210(const CycleValues& v, const CycleContext& ctx,
                                    CyclePath& path) {
    if (v.number(201) == 0.0) return std::nullopt;
    if (auto e = checkSlot(210, v, ctx)) return e;
    const double length = v.number(218);
    const double width = v.number(219);
    if (width > length) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the slot width Q219 is larger than its "
                                       "length Q218"),
                          {"210"}};
    }
    const Vec2 centre(v.number(216), v.number(217));
    const double angle = v.number(224) * kDegree;
    const Vec2 half = (length - width) / 2.0 * Vec2(std::cos(angle), std::sin(angle));
    const HoleLevels l = holeLevels(v, v.number(201));
    const int operation = v.integer(215);
    if (operation != 2) {
        rough(v, l, PlanarSegment::line(centre - half, centre + half), path);
        path.moveUv(centre, v.feed(207));
    } else {
        if ((path.w() - l.top) * l.up < 0.0) path.rapidW(l.top);
        path.rapidUv(centre);
    }
    if (operation == 1) {
        path.rapidW(l.top);
        return std::nullopt;
    }
    CycleValues m = finishing(kCycle253, v);
    m.set(218, length);
    m.set(374, v.number(224));
    return expandAs(210, kCycle253, m, ctx, path);
}

std::optional<CycleError> expand211(const CycleValues& v, const CycleContext& ctx,
                                    CyclePath& path) {
    if (v.number(201) == 0.0) return std::nullopt;
    if (auto e = checkSlot(211, v, ctx)) return e;
    const Vec2 centre(v.number(216), v.number(217));
    const double pitch = v.number(244) / 2.0;
    const double start = v.number(245) * kDegree;
    const HoleLevels l = holeLevels(v, v.number(201));
    const int operation = v.integer(215);
    if (operation != 2) {
        const Vec2 from = centre + pitch * Vec2(std::cos(start), std::sin(start));
        rough(v, l, PlanarSegment::arc(from, centre, v.number(248) * kDegree), path);
    }
    if (operation == 1) {
        path.rapidW(l.top);
        return std::nullopt;
    }
    CycleValues m = finishing(kCycle254, v);
    m.set(375, v.number(244));
    m.set(376, v.number(245));
    m.set(248, v.number(248));
    m.set(377, 1.0);
    m.set(378, 0.0);
    return expandAs(211, kCycle254, m, ctx, path);
}

}  // namespace

const CycleDescriptor kCycle210{.number = 210,
                                .name = KERF_TR_NOOP("SLOT RECIP. PLNG."),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kSlotParameters,
                                .expand = expand210,
                                .obsolete = true};
const CycleDescriptor kCycle211{.number = 211,
                                .name = KERF_TR_NOOP("CIRCULAR SLOT"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kCircularSlotParameters,
                                .expand = expand211,
                                .obsolete = true};

}  // namespace kerf::cycles
