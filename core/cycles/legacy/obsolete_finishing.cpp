// Obsolete cycles 212 POCKET FINISHING, 213 STUD FINISHING, 214 CIRCULAR POCKET FINISHING and
// 215 CIRCULAR STUD FINISHING (docs/cycles.md, "Obsolete Q-parameter cycles"): the walls of a
// pocket or stud centred on Q216/Q217, finished in Q202 infeeds with climb milling; run as
// cycles 251, 256, 252 and 257 with finishing only and no floor allowance.
#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/legacy/legacy_list.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace legacy;
using namespace pocket;

// The finishing pass of the pocket engine runs where an allowance is left; an allowance of 0
// in the old cycle still finishes the walls, so it is passed as this (it moves no wall).
constexpr double kLeastAllowance = 0.001;

constexpr ParameterDescriptor kCornerRadius{
    .q = 220,
    .description = KERF_TR_NOOP("Corner radius (0: tool radius)"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
constexpr ParameterDescriptor kAllowance{
    .q = 221,
    .description = KERF_TR_NOOP("Allowance in the 1st axis left by roughing"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
constexpr ParameterDescriptor kBlankDiameter{
    .q = 222,
    .description = KERF_TR_NOOP("Workpiece blank diameter"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 50.0};
constexpr ParameterDescriptor kFinishedDiameter{
    .q = 223,
    .description = KERF_TR_NOOP("Finished part diameter"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 50.0};

constexpr ParameterDescriptor kRectangleParameters[] = {
    common::kSetUpClearance,
    common::kDepth,
    kPlungeFeed,
    kPlungingDepth,
    kMillingFeed,
    common::kSurface,
    common::kSecondClearance,
    kCentreFirstAxis,
    kCentreSecondAxis,
    kFirstSide,
    kSecondSide,
    kCornerRadius,
    kAllowance,
};
constexpr ParameterDescriptor kCircleParameters[] = {
    common::kSetUpClearance,  common::kDepth,    kPlungeFeed,
    kPlungingDepth,           kMillingFeed,      common::kSurface,
    common::kSecondClearance, kCentreFirstAxis,  kCentreSecondAxis,
    kBlankDiameter,           kFinishedDiameter,
};

void copy(CycleValues& to, const CycleValues& from, std::initializer_list<uint16_t> qs) {
    for (uint16_t q : qs)
        to.set(q, from.number(q));
}

// The modern cycle's values: finishing only, the walls in Q202 infeeds (Q338), no floor
// allowance, climb milling, the old levels and feeds.
CycleValues finishingOnly(const CycleDescriptor& modern, const CycleValues& v, double allowance,
                          const CycleContext& ctx) {
    CycleValues m = defaultsOf(modern);
    copy(m, v, {200, 201, 203, 204});
    m.set(215, 2.0);
    m.set(368, std::max(allowance, kLeastAllowance));
    m.set(369, 0.0);
    m.set(338, v.number(202));
    m.set(202, v.number(202));
    m.set(351, 1.0);
    // The plunge strategy acts only when roughing; the modern cycles check it against the tool's
    // ANGLE all the same, so it is the one that tool allows.
    const double angle = ctx.tool.plungeAngleDeg;
    m.set(366, angle > 0.0 && angle != 90.0 ? 1.0 : 0.0);
    m.setFeed(206, v.feed(206));
    m.setFeed(207, v.feed(207));
    m.setFeed(385, v.feed(207));
    return m;
}

// To the 2nd set-up clearance (from above too, as the old manuals say), over the centre, the
// modern cycle from there, back over the centre.
std::optional<CycleError> finishAtCentre(int number, const CycleDescriptor& modern,
                                         const CycleValues& v, const CycleValues& m,
                                         const CycleContext& ctx, CyclePath& path) {
    if (v.number(201) == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(number, 201, v.number(201), ctx)) return e;
    const HoleLevels levels = holeLevels(v, v.number(201));
    const Vec2 centre(v.number(216), v.number(217));
    path.rapidW(levels.top);
    path.rapidUv(centre);
    if (auto e = expandAs(number, modern, m, ctx, path)) return e;
    path.rapidUv(centre);
    return std::nullopt;
}

std::optional<CycleError> expand212(const CycleValues& v, const CycleContext& ctx,
                                    CyclePath& path) {
    CycleValues m = finishingOnly(kCycle251, v, v.number(221), ctx);
    copy(m, v, {218, 219, 220});
    m.set(224, 0.0);
    m.set(367, 0.0);
    return finishAtCentre(212, kCycle251, v, m, ctx, path);
}

std::optional<CycleError> expand213(const CycleValues& v, const CycleContext& ctx,
                                    CyclePath& path) {
    CycleValues m = finishingOnly(kCycle256, v, v.number(221), ctx);
    copy(m, v, {218, 219, 220});
    m.set(424, v.number(218) + 2.0 * v.number(221));
    m.set(425, v.number(219) + 2.0 * v.number(221));
    m.set(224, 0.0);
    m.set(367, 0.0);
    return finishAtCentre(213, kCycle256, v, m, ctx, path);
}

std::optional<CycleError> expand214(const CycleValues& v, const CycleContext& ctx,
                                    CyclePath& path) {
    CycleValues m = finishingOnly(kCycle252, v, (v.number(223) - v.number(222)) / 2.0, ctx);
    m.set(223, v.number(223));
    return finishAtCentre(214, kCycle252, v, m, ctx, path);
}

std::optional<CycleError> expand215(const CycleValues& v, const CycleContext& ctx,
                                    CyclePath& path) {
    CycleValues m = finishingOnly(kCycle257, v, (v.number(222) - v.number(223)) / 2.0, ctx);
    m.set(222, v.number(222));
    m.set(223, v.number(223));
    m.set(376, 0.0);
    return finishAtCentre(215, kCycle257, v, m, ctx, path);
}

}  // namespace

const CycleDescriptor kCycle212{.number = 212,
                                .name = KERF_TR_NOOP("POCKET FINISHING"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kRectangleParameters,
                                .expand = expand212,
                                .obsolete = true};
const CycleDescriptor kCycle213{.number = 213,
                                .name = KERF_TR_NOOP("STUD FINISHING"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kRectangleParameters,
                                .expand = expand213,
                                .obsolete = true};
const CycleDescriptor kCycle214{.number = 214,
                                .name = KERF_TR_NOOP("CIRCULAR POCKET FINISHING"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kCircleParameters,
                                .expand = expand214,
                                .obsolete = true};
const CycleDescriptor kCycle215{.number = 215,
                                .name = KERF_TR_NOOP("CIRCULAR STUD FINISHING"),
                                .group = CycleGroup::PocketsStudsSlots,
                                .parameters = kCircleParameters,
                                .expand = expand215,
                                .obsolete = true};

}  // namespace kerf::cycles
