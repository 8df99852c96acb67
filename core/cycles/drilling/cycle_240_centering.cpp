// Cycle 240 CENTERING (spec §2): to a depth or to a countersink diameter.
#include <cmath>
#include <numbers>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance,
    {.q = 343,
     .description = KERF_TR_NOOP("Select depth (0) or diameter (1)"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 0.0,
     .integer = true},
    kDepth,
    {.q = 344,
     .description = KERF_TR_NOOP("Countersink diameter (sign = direction)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = -10.0},
    kPlungeFeed,
    kDwellDepth,
    kSurface,
    kSecondClearance,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const bool byDiameter = v.integer(343) == 1;
    const uint16_t q = byDiameter ? 344 : 201;
    const double signedValue = v.number(q);
    if (signedValue == 0.0) return std::nullopt;  // not executed
    if (auto e = checkDepthSign(240, q, signedValue, ctx)) return e;
    double depth = std::fabs(signedValue);
    if (byDiameter) {
        double cone = 0.0;  // cone length of the full tool radius
        if (auto e = coneLength(240, ctx.tool, cone)) return e;
        depth = depth / 2.0 / std::tan(ctx.tool.pointAngleDeg * std::numbers::pi / 360.0);
    }
    const HoleLevels l = holeLevels(v, signedValue);
    path.rapidW(l.clearance);
    path.moveW(l.at(depth), v.feed(206));
    path.dwell(v.number(211));
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle240{.number = 240,
                                .name = KERF_TR_NOOP("CENTERING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
