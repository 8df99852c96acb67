// Cycle 267 OUTSIDE THREAD MILLING (spec §3): from the stud centre to a start point outside the
// thread (thread radius + tool radius + 2 pitches on the main axis), optional front-face
// countersinking around the stud, then the thread passes of Q355. The tool ends above the start
// point at the 2nd set-up clearance.
#include <cmath>
#include <numbers>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/thread/thread_setup.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kNominalDiameter,
    kThreadPitch,
    kThreadDepth,
    kThreadsPerStep,
    kPrePositionFeed,
    kClimbOrUpCut,
    kSetUpClearance,
    kFrontDepth,
    {.q = 359,
     .description = KERF_TR_NOOP("Countersinking offset at front: stud centre to tool "
                                 "centre"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0},
    kSurface,
    kSecondClearance,
    kCountersinkFeed,
    kMillingFeed,
    kApproachFeed,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double threadDepth = v.number(201);
    const double frontDepth = v.number(358);
    const double direction = firstNonZero({threadDepth, frontDepth});
    if (direction == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(267, 201, threadDepth, ctx)) return e;
    if (auto e = checkDepthSign(267, 358, frontDepth, ctx)) return e;
    const HoleLevels l = holeLevels(v, direction);
    const bool towards = cutsTowardsSurface(v.number(239), v.integer(351), true);
    ThreadHelix helix;
    if (auto e =
            threadHelix(267, v, ctx, true, towards ? l.up : -l.up, v.feedOr(512, 207), helix)) {
        return e;
    }
    const Vec2 start = helix.centre + Vec2(helix.radius + 2.0 * helix.pitch, 0.0);
    path.rapidW(l.clearance);
    path.rapidUv(start);
    if (frontDepth != 0.0 && v.number(359) > 0.0) {
        const Feed feed = v.feed(254);
        const double dir = helix.ccw ? 1.0 : -1.0;
        const Vec2 out = helix.centre + Vec2(v.number(359), 0.0);
        path.moveW(l.at(std::fabs(frontDepth)), v.feed(253));
        path.moveUv(out, feed);
        path.arc({out.x(), out.y(), path.w()}, helix.centre, dir * 2.0 * std::numbers::pi, feed);
        path.moveUv(start, feed);
    }
    if (threadDepth != 0.0) {
        if (auto e =
                millThread(267, path, helix, l, std::fabs(threadDepth), v.integer(355), towards)) {
            return e;
        }
    }
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle267{.number = 267,
                                .name = KERF_TR_NOOP("OUTSIDE THREAD MILLING"),
                                .group = CycleGroup::ThreadMilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
