// Cycle 201 REAMING (spec §2): ream to depth, dwell, retract at Q208.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance, kDepth, kPlungeFeed, kDwellDepth, kRetractFeed, kSurface, kSecondClearance,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(201, 201, signedDepth, ctx)) return e;
    const HoleLevels l = holeLevels(v, signedDepth);
    path.rapidW(l.clearance);
    path.moveW(l.at(std::fabs(signedDepth)), v.feed(206));
    path.dwell(v.number(211));
    path.moveW(l.clearance, v.feedOr(208, 206));
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle201{.number = 201,
                                .name = KERF_TR_NOOP("REAMING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
