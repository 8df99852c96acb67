// Cycle 200 DRILLING (spec §2): pecking with full retraction, dwell Q211 at every infeed.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance, kDepth,   kPlungeFeed,      kPlungingDepth,
    kDwellTop,       kSurface, kSecondClearance, addedLater(kDwellDepth),
    kDepthReference,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(200, 201, signedDepth, ctx)) return e;
    double depth = std::fabs(signedDepth);
    if (v.integer(395) == 1) {
        double cone = 0.0;
        if (auto e = coneLength(200, ctx.tool, cone)) return e;
        depth += cone;
    }
    std::vector<double> infeeds;
    if (auto e = planInfeeds(200, depth, v.number(202), 0.0, 0.0, infeeds)) return e;
    const HoleLevels l = holeLevels(v, signedDepth);
    const Feed feed = v.feed(206);
    path.rapidW(l.clearance);
    for (size_t i = 0; i < infeeds.size(); ++i) {
        if (i > 0) {
            // Back down at rapid to the set-up clearance above the depth reached.
            path.rapidW(l.at(infeeds[i - 1]) + l.up * v.number(200));
        }
        path.moveW(l.at(infeeds[i]), feed);
        path.dwell(v.number(211));
        if (i + 1 < infeeds.size()) {
            path.rapidW(l.clearance);
            path.dwell(v.number(210));
        }
    }
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle200{.number = 200,
                                .name = KERF_TR_NOOP("DRILLING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
