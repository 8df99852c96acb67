// Cycle 241 SINGLE-LIP DEEP-HOLE DRILLING (spec §2): entry at speed Q427 in direction Q426,
// coolant on at the drilling start (Q379 rule), drilling at Q428 in infeeds (dwell Q211 after
// each, feed reduced to Q401 % beyond the dwell depth Q435), coolant off and entry speed at the
// bottom, retraction at Q208, 2nd set-up clearance, then the spindle as before the cycle.
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
    kDwellDepth,
    kSurface,
    kSecondClearance,
    kStartingPoint,
    kPrePositionFeed,
    kRetractFeed,
    {.q = 426,
     .description = KERF_TR_NOOP("Direction of rotation for entry and exit (3 M3, 4 M4, "
                                 "5 stationary)"),
     .min = 3.0,
     .max = 5.0,
     .defaultValue = 5.0,
     .integer = true},
    {.q = 427,
     .description = KERF_TR_NOOP("Spindle speed for entry and exit"),
     .unit = Unit::Rpm,
     .min = 0.0,
     .max = 99999.0,
     .defaultValue = 25.0},
    {.q = 428,
     .description = KERF_TR_NOOP("Spindle speed for drilling"),
     .unit = Unit::Rpm,
     .min = 0.0,
     .max = 99999.0,
     .defaultValue = 500.0},
    {.q = 429,
     .description = KERF_TR_NOOP("M function for coolant on (0: none)"),
     .min = 0.0,
     .max = 999.0,
     .defaultValue = 0.0,
     .integer = true},
    {.q = 430,
     .description = KERF_TR_NOOP("M function for coolant off (0: none)"),
     .min = 0.0,
     .max = 999.0,
     .defaultValue = 0.0,
     .integer = true},
    {.q = 435,
     .description = KERF_TR_NOOP("Dwell depth where the feed reduction begins (0: "
                                 "none)"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0,
     .optional = true},
    {.q = 401,
     .description = KERF_TR_NOOP("Feed rate factor beyond the dwell depth"),
     .unit = Unit::Percent,
     .min = 0.0,
     .max = 100.0,
     .defaultValue = 100.0,
     .optional = true},
    {.q = 202,
     .description = KERF_TR_NOOP("Maximum plunging depth"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0,
     .optional = true},
    {.q = 212,
     .description = KERF_TR_NOOP("Decrement of the plunging depth after each infeed"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0,
     .optional = true},
    {.q = 205,
     .description = KERF_TR_NOOP("Minimum plunging depth when decreasing"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0,
     .optional = true},
};

canon::SpindleDirection entryDirection(int q426) {
    if (q426 == 3) return canon::SpindleDirection::Clockwise;
    if (q426 == 4) return canon::SpindleDirection::CounterClockwise;
    return canon::SpindleDirection::Stopped;
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(241, 201, signedDepth, ctx)) return e;
    const double depth = std::fabs(signedDepth);
    const double start = v.number(379);
    if (start >= depth) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the starting point Q379 lies at or below the "
                                       "depth"),
                          {"241"}};
    }
    std::vector<double> infeeds;
    if (auto e =
            planInfeeds(241, depth - start, v.number(202), v.number(212), v.number(205), infeeds)) {
        return e;
    }
    const HoleLevels l = holeLevels(v, signedDepth);
    const DeepenedStart s = deepenedStart(l, start, v.number(200));
    const canon::SpindleDirection entry = entryDirection(v.integer(426));
    const canon::SpindleDirection drilling =
        ctx.spindle == canon::SpindleDirection::CounterClockwise
            ? canon::SpindleDirection::CounterClockwise
            : canon::SpindleDirection::Clockwise;
    const Feed feed = v.feed(206);
    Feed reduced = feed;
    reduced.value = feed.value * v.number(401) / 100.0;
    const double slowFrom = v.number(435);

    path.rapidW(l.clearance);
    path.spindle(entry, v.number(427));
    path.moveW(s.drillStart, v.feed(253));
    if (v.integer(429) > 0) path.miscFunction(v.integer(429));
    path.spindle(drilling, v.number(428));
    double reached = start;
    for (double infeed : infeeds) {
        const double target = start + infeed;
        if (slowFrom > 0.0 && reached < slowFrom && slowFrom < target) {
            path.moveW(l.at(slowFrom), feed);
            reached = slowFrom;
        }
        path.moveW(l.at(target), slowFrom > 0.0 && reached >= slowFrom ? reduced : feed);
        path.dwell(v.number(211));
        reached = target;
    }
    if (v.integer(430) > 0) path.miscFunction(v.integer(430));
    path.spindle(entry, v.number(427));
    path.moveW(s.retract, v.feedOr(208, 206));
    path.rapidW(l.top);
    path.spindle(ctx.spindle, ctx.spindleRpm);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle241{.number = 241,
                                .name = KERF_TR_NOOP("SINGLE-LIP DEEP-HOLE DRILLING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
