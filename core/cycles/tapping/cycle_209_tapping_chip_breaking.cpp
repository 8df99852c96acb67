// Cycle 209 TAPPING WITH CHIP BREAKING (spec §3): spindle oriented to Q336 at the set-up
// clearance, synchronised infeeds of Q257, after each a synchronised retraction by Q256 x pitch
// (Q256 = 0: out of the hole), back to the set-up clearance at the end where the spindle stops.
// The retraction speed factor Q403 is left to the machine: the canonical move has no speed.
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
    kThreadPitch,
    kSurface,
    kSecondClearance,
    kChipBreakDepth,
    {.q = 256,
     .description = KERF_TR_NOOP("Retraction for chip breaking in pitches (0: out of "
                                 "the hole)"),
     .unit = Unit::Factor,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 1.0},
    kSpindleAngle,
    {.q = 403,
     .description = KERF_TR_NOOP("Spindle speed factor for retraction"),
     .unit = Unit::Factor,
     .min = 0.0001,
     .max = 10.0,
     .defaultValue = 1.0,
     .optional = true},
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(209, 201, signedDepth, ctx)) return e;
    const double lead = v.number(239);
    if (auto e = checkPitchNotZero(209, 239, lead)) return e;
    if (auto e = checkToolPitch(209, ctx.tool, lead)) return e;
    const double depth = std::fabs(signedDepth);
    std::vector<double> infeeds;
    if (auto e = planInfeeds(209, depth, v.number(257), 0.0, 0.0, infeeds)) return e;
    const HoleLevels l = holeLevels(v, signedDepth);
    const double back = v.number(256) * std::fabs(lead);
    double angle = v.number(336);
    auto thread = [&](double w) {
        const double from = path.w();
        path.threadMove({path.position().x(), path.position().y(), w}, lead, angle);
        angle = spindleAngleAfter(angle, w - from, lead);
    };
    path.rapidW(l.clearance);
    path.orientSpindle(angle);
    for (size_t i = 0; i < infeeds.size(); ++i) {
        thread(l.at(infeeds[i]));
        if (i + 1 < infeeds.size())
            thread(back > 0.0 ? l.at(infeeds[i]) + l.up * back : l.clearance);
    }
    thread(l.clearance);
    path.spindle(canon::SpindleDirection::Stopped, ctx.spindleRpm);
    path.rapidW(l.top);
    if (ctx.spindle != canon::SpindleDirection::Stopped) path.spindle(ctx.spindle, ctx.spindleRpm);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle209{.number = 209,
                                .name = KERF_TR_NOOP("TAPPING WITH CHIP BREAKING"),
                                .group = CycleGroup::Tapping,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
