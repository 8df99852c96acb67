// Cycle 207 RIGID TAPPING (spec §3): a spindle-synchronised move to the depth and back to the
// set-up clearance (lead = pitch Q239, its sign the hand); the spindle stops there, the tool goes
// to the 2nd set-up clearance and the spindle runs again if it ran before.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/tapping/tapping_checks.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance, kThreadDepth, kThreadPitch, kSurface, kSecondClearance,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(207, 201, signedDepth, ctx)) return e;
    const double lead = v.number(239);
    if (auto e = checkPitchNotZero(207, 239, lead)) return e;
    if (auto e = checkToolPitch(207, ctx.tool, lead)) return e;
    const HoleLevels l = holeLevels(v, signedDepth);
    const double bottom = l.at(std::fabs(signedDepth));
    path.rapidW(l.clearance);
    path.threadMove({path.position().x(), path.position().y(), bottom}, lead, 0.0);
    const double angle = spindleAngleAfter(0.0, l.clearance - bottom, lead);
    path.threadMove({path.position().x(), path.position().y(), l.clearance}, lead, angle);
    path.spindle(canon::SpindleDirection::Stopped, ctx.spindleRpm);
    path.rapidW(l.top);
    if (ctx.spindle != canon::SpindleDirection::Stopped) path.spindle(ctx.spindle, ctx.spindleRpm);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle207{.number = 207,
                                .name = KERF_TR_NOOP("RIGID TAPPING"),
                                .group = CycleGroup::Tapping,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
