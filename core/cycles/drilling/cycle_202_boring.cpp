// Cycle 202 BORING (spec §2): bore, dwell, orient the spindle, disengage 0.2 mm, retract.
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/disengage.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr double kDisengageMm = 0.2;  // fixed by the TNC

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance, kDepth,           kPlungeFeed,         kDwellDepth,   kRetractFeed,
    kSurface,        kSecondClearance, kDisengageDirection, kSpindleAngle,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(202, 201, signedDepth, ctx)) return e;
    const HoleLevels l = holeLevels(v, signedDepth);
    const Vec2 centre = path.uv();
    path.rapidW(l.clearance);
    path.moveW(l.at(std::fabs(signedDepth)), v.feed(206));
    path.dwell(v.number(211));
    path.orientSpindle(v.number(336));
    path.rapidUv(centre + kDisengageMm * disengageDirection(v.integer(214), ctx));
    path.moveW(l.clearance, v.feedOr(208, 206));
    path.rapidW(l.top);
    path.rapidUv(centre);
    restoreSpindle(path, ctx);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle202{.number = 202,
                                .name = KERF_TR_NOOP("BORING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
