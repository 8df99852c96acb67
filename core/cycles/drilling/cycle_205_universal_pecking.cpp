// Cycle 205 UNIVERSAL PECKING (spec §2): deepened start Q379, infeeds decreasing by Q212 down to
// Q205, chip breaks every Q257 of travel within an infeed (back Q256, re-approach at Q253), and
// after each infeed a rapid retraction to the chip-removal position and a rapid re-approach to the
// advanced stop distance above the depth reached (Q258 after the first retraction, Q259 after the
// last, linear in between).
#include <cmath>

#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/deepened_start.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance,
    kDepth,
    kPlungeFeed,
    kPlungingDepth,
    kSurface,
    kSecondClearance,
    kDecrement,
    kMinPlungingDepth,
    kUpperAdvancedStop,
    {.q = 259,
     .description = KERF_TR_NOOP("Lower advanced stop distance"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.2},
    kChipBreakDepth,
    kChipBreakRetract,
    kDwellDepth,
    kStartingPoint,
    kPrePositionFeed,
    {.q = 208,
     .description = KERF_TR_NOOP("Retraction feed rate (0: plunging feed)"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0,
     .keywords = kFeedAuto | kFeedMax,
     .predef = true,
     .optional = true},
    kDepthReference,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(205, 201, signedDepth, ctx)) return e;
    double depth = std::fabs(signedDepth);
    if (v.integer(395) == 1) {
        double cone = 0.0;
        if (auto e = coneLength(205, ctx.tool, cone)) return e;
        depth += cone;
    }
    const double start = v.number(379);
    if (start >= depth) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the starting point Q379 lies at or below the "
                                       "depth"),
                          {"205"}};
    }
    std::vector<double> infeeds;
    if (auto e =
            planInfeeds(205, depth - start, v.number(202), v.number(212), v.number(205), infeeds)) {
        return e;
    }
    const HoleLevels l = holeLevels(v, signedDepth);
    const DeepenedStart s = deepenedStart(l, start, v.number(200));
    const double chipDepth = v.number(257);
    if (chipDepth > 0.0 && depth / chipDepth > static_cast<double>(CyclePath::kMoveLimit)) {
        return tooManyMoves(205);
    }
    const size_t retractions = infeeds.size() - 1;
    path.rapidW(l.clearance);
    path.moveW(s.drillStart, v.feed(253));
    double reached = start;
    for (size_t i = 0; i < infeeds.size(); ++i) {
        const double target = start + infeeds[i];
        if (chipDepth > 0.0) {
            for (double brk = reached + chipDepth; brk < target - 1e-9; brk += chipDepth) {
                path.moveW(l.at(brk), v.feed(206));
                path.rapidW(l.at(brk) + l.up * v.number(256));
                path.moveW(l.at(brk), v.feed(253));
            }
        }
        path.moveW(l.at(target), v.feed(206));
        reached = target;
        if (i == retractions) break;
        path.rapidW(s.retract);
        const double upper = v.number(258), lower = v.number(259);
        const double stop = retractions <= 1 ? upper
                                             : upper + (lower - upper) * static_cast<double>(i) /
                                                           static_cast<double>(retractions - 1);
        path.rapidW(l.at(target) + l.up * stop);
    }
    path.dwell(v.number(211));
    path.moveW(s.retract, v.feedOr(208, 206));
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle205{.number = 205,
                                .name = KERF_TR_NOOP("UNIVERSAL PECKING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
