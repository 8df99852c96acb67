// Cycle 262 THREAD MILLING (spec §3).
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/thread/thread_setup.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kNominalDiameter, kThreadPitch,  kThreadDepth,    kThreadsPerStep,
    kPrePositionFeed, kClimbOrUpCut, kSetUpClearance, kSurface,
    kSecondClearance, kMillingFeed,  kApproachFeed,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(262, 201, signedDepth, ctx)) return e;
    const HoleLevels l = holeLevels(v, signedDepth);
    const bool towards = cutsTowardsSurface(v.number(239), v.integer(351), false);
    ThreadHelix helix;
    if (auto e =
            threadHelix(262, v, ctx, false, towards ? l.up : -l.up, v.feedOr(512, 207), helix)) {
        return e;
    }
    path.rapidW(l.clearance);
    if (auto e = millThread(262, path, helix, l, std::fabs(signedDepth), v.integer(355), towards)) {
        return e;
    }
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle262{.number = 262,
                                .name = KERF_TR_NOOP("THREAD MILLING"),
                                .group = CycleGroup::ThreadMilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
