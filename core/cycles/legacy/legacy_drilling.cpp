// Legacy cycles 1 PECKING, 2 TAPPING and 17 RIGID TAPPING (docs/cycles.md). Pecking has its
// own sequence (advanced stop distance by depth); the tapping cycles run as 206 and 207.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/translate.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/legacy/legacy_list.h"

namespace kerf::cycles {

namespace legacy {

CycleValues defaultsOf(const CycleDescriptor& modern) {
    CycleValues values;
    for (const ParameterDescriptor& p : modern.parameters)
        values.set(p.q, p.defaultValue);
    return values;
}

void setStartLevels(CycleValues& modern, double start, double setUp, double depth) {
    const double clearance = std::fabs(setUp);
    modern.set(200, clearance);
    modern.set(203, depth > 0.0 ? start + clearance : start - clearance);
    modern.set(204, 0.0);
}

std::optional<CycleError> expandAs(int legacyNumber, const CycleDescriptor& modern,
                                   const CycleValues& values, const CycleContext& context,
                                   CyclePath& path) {
    std::optional<CycleError> error = modern.expand(values, context, path);
    // The cycle's number comes first in the messages ("cycle {1} needs a tool ...").
    if (error && !error->args.empty() && error->args[0] == std::to_string(modern.number))
        error->args[0] = std::to_string(legacyNumber);
    return error;
}

}  // namespace legacy

namespace {

using namespace legacy;

constexpr ParameterDescriptor kDwell{.word = "DWELL",
                                     .description = KERF_TR_NOOP("Dwell time at the bottom"),
                                     .unit = Unit::Seconds,
                                     .min = 0.0,
                                     .max = 3600.0,
                                     .optional = true};
constexpr ParameterDescriptor kPeckingParameters[] = {
    kSetUp, kLegacyDepth, kPeckingDepth, kDwell, kFeed,
};

// Advanced stop distance of the old pecking cycle: 0.6 mm up to 30 mm depth, then depth / 50,
// at most 7 mm.
double advancedStop(double depth) {
    return depth <= 30.0 ? 0.6 : std::min(7.0, depth / 50.0);
}

std::optional<CycleError> expandPecking(const CycleValues& v, const CycleContext& ctx,
                                        CyclePath& path) {
    const double signedDepth = v.number(2);
    if (signedDepth == 0.0) return std::nullopt;
    const double depth = std::fabs(signedDepth);
    CycleValues levels;
    legacy::setStartLevels(levels, ctx.start.z(), v.number(1), signedDepth);
    const HoleLevels l = holeLevels(levels, signedDepth);
    std::vector<double> infeeds;
    if (auto e = planInfeeds(1, depth, std::fabs(v.number(3)), 0.0, 0.0, infeeds)) return e;
    const double stop = advancedStop(depth);
    for (size_t i = 0; i < infeeds.size(); ++i) {
        path.moveW(l.at(infeeds[i]), v.feed(5));
        if (i + 1 == infeeds.size()) break;
        path.rapidW(l.clearance);  // out of the hole to the starting position
        path.rapidW(l.at(infeeds[i]) + l.up * stop);
    }
    path.dwell(v.number(4));
    path.rapidW(l.clearance);
    return std::nullopt;
}

constexpr ParameterDescriptor kTappingParameters[] = {kSetUp, kLegacyDepth, kDwell, kFeed};

std::optional<CycleError> expandTapping(const CycleValues& v, const CycleContext& ctx,
                                        CyclePath& path) {
    CycleValues modern = legacy::defaultsOf(kCycle206);
    legacy::setStartLevels(modern, ctx.start.z(), v.number(1), v.number(2));
    modern.set(201, v.number(2));
    modern.setFeed(206, v.feed(4));
    modern.set(211, v.number(3));
    return expandAs(2, kCycle206, modern, ctx, path);
}

constexpr ParameterDescriptor kRigidTappingParameters[] = {
    kSetUp,
    kLegacyDepth,
    {.word = "PITCH",
     .description = KERF_TR_NOOP("Thread pitch (+ right-hand, - left-hand)"),
     .unit = Unit::Millimetre,
     .min = -99.9999,
     .max = 99.9999}};

std::optional<CycleError> expandRigidTapping(const CycleValues& v, const CycleContext& ctx,
                                             CyclePath& path) {
    CycleValues modern = legacy::defaultsOf(kCycle207);
    legacy::setStartLevels(modern, ctx.start.z(), v.number(1), v.number(2));
    modern.set(201, v.number(2));
    modern.set(239, v.number(3));
    return expandAs(17, kCycle207, modern, ctx, path);
}

}  // namespace

const CycleDescriptor kCycle1{.number = 1,
                              .name = KERF_TR_NOOP("PECKING"),
                              .group = CycleGroup::Drilling,
                              .oldStyle = true,
                              .parameters = kPeckingParameters,
                              .expand = expandPecking};
const CycleDescriptor kCycle2{.number = 2,
                              .name = KERF_TR_NOOP("TAPPING"),
                              .group = CycleGroup::Tapping,
                              .oldStyle = true,
                              .parameters = kTappingParameters,
                              .expand = expandTapping};
const CycleDescriptor kCycle17{.number = 17,
                               .name = KERF_TR_NOOP("RIGID TAPPING"),
                               .group = CycleGroup::Tapping,
                               .oldStyle = true,
                               .parameters = kRigidTappingParameters,
                               .expand = expandRigidTapping};

}  // namespace kerf::cycles
