// Cycle 263 THREAD MILLING/COUNTERSINKING (spec §3): countersinking on the thread diameter at
// Q356, front-face countersinking at Q358 (circle of radius Q359), then one 360° thread helix.
// A depth of 0 skips its step; the first non-zero depth gives the working direction.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/thread/thread_setup.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kNominalDiameter, kThreadPitch,     kThreadDepth,     kCountersinkDepth, kPrePositionFeed,
    kClimbOrUpCut,    kSetUpClearance,  kSideClearance,   kFrontDepth,       kFrontOffset,
    kSurface,         kSecondClearance, kCountersinkFeed, kMillingFeed,      kApproachFeed,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double threadDepth = v.number(201);
    const double sinkDepth = v.number(356);
    const double frontDepth = v.number(358);
    const double direction = firstNonZero({threadDepth, sinkDepth, frontDepth});
    if (direction == 0.0) return std::nullopt;
    for (uint16_t q : {uint16_t{201}, uint16_t{356}, uint16_t{358}}) {
        if (auto e = checkDepthSign(263, q, v.number(q), ctx)) return e;
    }
    const HoleLevels l = holeLevels(v, direction);
    const bool towards = cutsTowardsSurface(v.number(239), v.integer(351), false);
    ThreadHelix helix;
    if (auto e =
            threadHelix(263, v, ctx, false, towards ? l.up : -l.up, v.feedOr(512, 207), helix)) {
        return e;
    }
    path.rapidW(l.clearance);
    if (sinkDepth != 0.0) {
        path.moveW(l.at(std::fabs(sinkDepth)), v.feed(253));
        frontCircle(path, helix.centre, helix.radius, helix.ccw, v.feed(254));
    }
    if (frontDepth != 0.0) {
        path.moveW(l.at(std::fabs(frontDepth)), v.feed(253));
        frontCircle(path, helix.centre, v.number(359), helix.ccw, v.feed(254));
    }
    if (threadDepth != 0.0) {
        if (auto e = millThread(263, path, helix, l, std::fabs(threadDepth), 0, towards)) return e;
    }
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle263{.number = 263,
                                .name = KERF_TR_NOOP("THREAD MILLING/COUNTERSINKING"),
                                .group = CycleGroup::ThreadMilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
