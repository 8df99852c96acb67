// Cycle 206 TAPPING WITH A FLOATING TAP HOLDER (spec §3): tap to depth at Q206, reverse the
// spindle, dwell, retract at Q206, spindle back to its direction, 2nd set-up clearance.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/tapping/tapping_checks.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance,
    kThreadDepth,
    {.q = 206,
     .description = KERF_TR_NOOP("Feed rate for tapping (spindle speed x pitch)"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 150.0,
     .keywords = kFeedAuto},
    kDwellDepth,
    kSurface,
    kSecondClearance,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(206, 201, signedDepth, ctx)) return e;
    if (ctx.spindle == canon::SpindleDirection::Stopped) {
        return CycleError{"cycle-spindle",
                          KERF_TR_NOOP("cycle {1} needs the spindle running (M3 or M4)"),
                          {"206"}};
    }
    const Feed feed = v.feed(206);
    // The tap's pitch is the feed per revolution.
    const double pitch = feed.kind == Feed::Kind::PerRevolution ? feed.value
                         : ctx.spindleRpm > 0.0                 ? feed.value / ctx.spindleRpm
                                                                : 0.0;
    if (pitch > 0.0) {
        if (auto e = checkToolPitch(206, ctx.tool, pitch)) return e;
    }
    const canon::SpindleDirection reverse = ctx.spindle == canon::SpindleDirection::Clockwise
                                                ? canon::SpindleDirection::CounterClockwise
                                                : canon::SpindleDirection::Clockwise;
    const HoleLevels l = holeLevels(v, signedDepth);
    path.rapidW(l.clearance);
    path.moveW(l.at(std::fabs(signedDepth)), feed);
    path.spindle(reverse, ctx.spindleRpm);
    path.dwell(v.number(211));
    path.moveW(l.clearance, feed);
    path.spindle(ctx.spindle, ctx.spindleRpm);
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle206{.number = 206,
                                .name = KERF_TR_NOOP("TAPPING WITH A FLOATING TAP HOLDER"),
                                .group = CycleGroup::Tapping,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
