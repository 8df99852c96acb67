// Cycle 265 HELICAL THREAD DRILLING/MILLING (spec §3): front-face countersinking before (Q360 = 0,
// plunge at Q254) or after (Q360 = 1, plunge at Q253) the thread; the thread is one continuous
// helix from the surface down to the depth, its direction of rotation given by the hand alone.
#include <cmath>

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
    kPrePositionFeed,
    kFrontDepth,
    kFrontOffset,
    {.q = 360,
     .description = KERF_TR_NOOP("Countersink before (0) or after (1) the thread"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 0.0,
     .integer = true},
    kSetUpClearance,
    kSurface,
    kSecondClearance,
    kCountersinkFeed,
    kMillingFeed,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double threadDepth = v.number(201);
    const double frontDepth = v.number(358);
    const double direction = firstNonZero({threadDepth, frontDepth});
    if (direction == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(265, 201, threadDepth, ctx)) return e;
    if (auto e = checkDepthSign(265, 358, frontDepth, ctx)) return e;
    const HoleLevels l = holeLevels(v, direction);
    ThreadHelix helix;
    if (auto e = threadHelix(265, v, ctx, false, -l.up, v.feed(207), helix)) return e;
    const bool after = v.integer(360) == 1;
    auto front = [&](const Feed& plunge) {
        if (frontDepth == 0.0) return;
        path.moveW(l.at(std::fabs(frontDepth)), plunge);
        frontCircle(path, helix.centre, v.number(359), helix.ccw, v.feed(254));
    };
    path.rapidW(l.clearance);
    if (!after) front(v.feed(254));
    if (threadDepth != 0.0) {
        if (auto e = millThread(265, path, helix, l, std::fabs(threadDepth), 1, false)) return e;
    }
    if (after) front(v.feed(253));
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle265{.number = 265,
                                .name = KERF_TR_NOOP("HELICAL THREAD DRILLING/MILLING"),
                                .group = CycleGroup::ThreadMilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
