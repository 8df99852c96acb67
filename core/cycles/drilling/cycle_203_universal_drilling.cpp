// Cycle 203 UNIVERSAL DRILLING (spec §2): infeeds decreasing by Q212 down to Q205; after each
// infeed either a chip break (back by Q256) or, once Q213 breaks are done (or without chip
// breaking), a retraction out of the hole at Q208 with dwell Q210.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance,
    kDepth,
    kPlungeFeed,
    kPlungingDepth,
    kDwellTop,
    kSurface,
    kSecondClearance,
    kDecrement,
    {.q = 213,
     .description = KERF_TR_NOOP("Number of chip breaks before retracting"),
     .unit = Unit::Count,
     .min = 0.0,
     .max = 99999.0,
     .defaultValue = 0.0,
     .integer = true},
    kMinPlungingDepth,
    kDwellDepth,
    kRetractFeed,
    kChipBreakRetract,
    kDepthReference,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(203, 201, signedDepth, ctx)) return e;
    double depth = std::fabs(signedDepth);
    if (v.integer(395) == 1) {
        double cone = 0.0;
        if (auto e = coneLength(203, ctx.tool, cone)) return e;
        depth += cone;
    }
    std::vector<double> infeeds;
    if (auto e = planInfeeds(203, depth, v.number(202), v.number(212), v.number(205), infeeds)) {
        return e;
    }
    const HoleLevels l = holeLevels(v, signedDepth);
    const int breaksAllowed = v.integer(213);
    const double chipRetract = v.number(256);
    int breaks = 0;
    path.rapidW(l.clearance);
    for (size_t i = 0; i < infeeds.size(); ++i) {
        path.moveW(l.at(infeeds[i]), v.feed(206));
        if (i + 1 == infeeds.size()) break;
        if (breaksAllowed > 0 && breaks < breaksAllowed) {
            path.rapidW(l.at(infeeds[i]) + l.up * chipRetract);
            ++breaks;
            continue;
        }
        path.moveW(l.clearance, v.feedOr(208, 206));
        path.dwell(v.number(210));
        // Back into the hole at rapid, stopping short of the depth reached.
        const double stop = breaksAllowed > 0 ? chipRetract : v.number(200);
        path.rapidW(l.at(infeeds[i]) + l.up * stop);
        breaks = 0;
    }
    path.dwell(v.number(211));
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle203{.number = 203,
                                .name = KERF_TR_NOOP("UNIVERSAL DRILLING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
