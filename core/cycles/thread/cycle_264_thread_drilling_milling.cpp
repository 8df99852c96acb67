// Cycle 264 THREAD DRILLING/MILLING (spec §3): drilling to Q356 in infeeds of Q202 (chip break
// back by Q256 when Q257 > 0, otherwise out to the set-up clearance and back at rapid to Q258
// above the depth reached), front-face countersinking at Q206 (no Q254 in this cycle), then one
// 360° thread helix.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/thread/thread_setup.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kNominalDiameter, kThreadPitch,   kThreadDepth,       kHoleDepth,      kPrePositionFeed,
    kClimbOrUpCut,    kPlungingDepth, kUpperAdvancedStop, kChipBreakDepth, kChipBreakRetract,
    kFrontDepth,      kFrontOffset,   kSetUpClearance,    kSurface,        kSecondClearance,
    kPlungeFeed,      kMillingFeed,   kApproachFeed,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double threadDepth = v.number(201);
    const double holeDepth = v.number(356);
    const double frontDepth = v.number(358);
    const double direction = firstNonZero({threadDepth, holeDepth, frontDepth});
    if (direction == 0.0) return std::nullopt;
    for (uint16_t q : {uint16_t{201}, uint16_t{356}, uint16_t{358}}) {
        if (auto e = checkDepthSign(264, q, v.number(q), ctx)) return e;
    }
    const HoleLevels l = holeLevels(v, direction);
    const bool towards = cutsTowardsSurface(v.number(239), v.integer(351), false);
    ThreadHelix helix;
    if (auto e =
            threadHelix(264, v, ctx, false, towards ? l.up : -l.up, v.feedOr(512, 207), helix)) {
        return e;
    }
    path.rapidW(l.clearance);
    if (holeDepth != 0.0) {
        std::vector<double> infeeds;
        if (auto e = planInfeeds(264, std::fabs(holeDepth), v.number(202), 0.0, 0.0, infeeds)) {
            return e;
        }
        for (size_t i = 0; i < infeeds.size(); ++i) {
            path.moveW(l.at(infeeds[i]), v.feed(206));
            if (i + 1 == infeeds.size()) break;
            if (v.number(257) > 0.0) {
                path.rapidW(l.at(infeeds[i]) + l.up * v.number(256));
            } else {
                path.rapidW(l.clearance);
                path.rapidW(l.at(infeeds[i]) + l.up * v.number(258));
            }
        }
    }
    if (frontDepth != 0.0) {
        path.moveW(l.at(std::fabs(frontDepth)), v.feed(253));
        frontCircle(path, helix.centre, v.number(359), helix.ccw, v.feed(206));
    }
    if (threadDepth != 0.0) {
        if (auto e = millThread(264, path, helix, l, std::fabs(threadDepth), 0, towards)) return e;
    }
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle264{.number = 264,
                                .name = KERF_TR_NOOP("THREAD DRILLING/MILLING"),
                                .group = CycleGroup::ThreadMilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
