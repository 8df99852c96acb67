// Cycle 204 BACK BORING (spec §2): counterbore on the underside with a reverse boring bar.
// The tool length is measured to the underside of the bar; its cutting edge is Q252 above.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/disengage.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance,
    {.q = 249,
     .description = KERF_TR_NOOP("Depth of counterbore from the underside (+ upwards)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 5.0},
    {.q = 250,
     .description = KERF_TR_NOOP("Material thickness"),
     .unit = Unit::Millimetre,
     .min = 0.0001,
     .max = kLength,
     .defaultValue = 20.0},
    {.q = 251,
     .description = KERF_TR_NOOP("Off-centre distance of the boring bar"),
     .unit = Unit::Millimetre,
     .min = 0.0001,
     .max = kLength,
     .defaultValue = 3.5},
    {.q = 252,
     .description = KERF_TR_NOOP("Tool edge height above the underside of the bar"),
     .unit = Unit::Millimetre,
     .min = 0.0001,
     .max = kLength,
     .defaultValue = 15.0},
    kPrePositionFeed,
    {.q = 254,
     .description = KERF_TR_NOOP("Feed rate for counterboring"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 200.0,
     .keywords = kFeedAuto | kFeedPerRev},
    {.q = 255,
     .description = KERF_TR_NOOP("Dwell time at the counterbore floor"),
     .unit = Unit::Seconds,
     .min = 0.0,
     .max = 3600.0,
     .defaultValue = 0.0},
    kSurface,
    kSecondClearance,
    {.q = 214,
     .description = KERF_TR_NOOP("Disengaging direction (1 -main, 2 -secondary, 3 +main, "
                                 "4 +secondary axis)"),
     .min = 1.0,
     .max = 4.0,
     .defaultValue = 1.0,
     .integer = true},
    kSpindleAngle,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double counterbore = v.number(249);
    if (counterbore == 0.0) return std::nullopt;
    const double surface = v.number(203);
    const double underside = surface - v.number(250);
    const double clearance = v.number(200);
    const double edge = v.number(252);
    const Vec2 centre = path.uv();
    const Vec2 offset = centre + v.number(251) * disengageDirection(v.integer(214), ctx);
    const Feed prePosition = v.feed(253);
    const canon::SpindleDirection turning = ctx.spindle == canon::SpindleDirection::Stopped
                                                ? canon::SpindleDirection::Clockwise
                                                : ctx.spindle;
    path.rapidW(surface + clearance);
    path.orientSpindle(v.number(336));
    path.rapidUv(offset);
    // Plunge until the cutting edge is the set-up clearance below the underside.
    const double below = underside - clearance - edge;
    path.moveW(below, prePosition);
    path.moveUv(centre, prePosition);
    path.spindle(turning, ctx.spindleRpm);
    path.moveW(underside + counterbore - edge, v.feed(254));
    path.dwell(v.number(255));
    path.moveW(below, prePosition);
    path.orientSpindle(v.number(336));
    path.moveUv(offset, prePosition);
    path.moveW(surface + clearance, prePosition);
    path.rapidW(surface + std::max(clearance, v.number(204)));
    path.rapidUv(centre);
    restoreSpindle(path, ctx);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle204{.number = 204,
                                .name = KERF_TR_NOOP("BACK BORING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
