// Cycle 232 FACE MILLING (spec §10). Infeeds: the depth Q227 - Q386 less the finishing allowance
// Q369 in equal roughing infeeds of at most Q202, then one finishing pass at Q385. Paths: tool
// centre lines along the main axis from Q226 to Q226 + Q219 at an equal stepover of at most
// Q370 x (R - R2). Strategy 0 and 2 start and end the paths the tool radius plus Q357 beyond the
// surface; strategy 1 turns on the edges. Every other infeed machines the paths in reverse order.
#include <algorithm>
#include <cmath>

#include "core/base/fixed_format.h"
#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr size_t kMaxPaths = 10000;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 389,
     .description = KERF_TR_NOOP("Strategy (0 meander outside, 1 meander on the edge, 2 "
                                 "line by line)"),
     .min = 0.0,
     .max = 2.0,
     .defaultValue = 0.0,
     .integer = true},
    {.q = 225,
     .description = KERF_TR_NOOP("Starting point in the 1st axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength},
    {.q = 226,
     .description = KERF_TR_NOOP("Starting point in the 2nd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength},
    {.q = 227,
     .description = KERF_TR_NOOP("Starting point in the 3rd axis (surface)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength},
    {.q = 386,
     .description = KERF_TR_NOOP("End point in the 3rd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength},
    {.q = 218,
     .description = KERF_TR_NOOP("First side length (sign = direction)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 100.0},
    {.q = 219,
     .description = KERF_TR_NOOP("Second side length (sign = direction)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 202,
     .description = KERF_TR_NOOP("Maximum plunging depth"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 2.0},
    {.q = 369,
     .description = KERF_TR_NOOP("Finishing allowance for the floor"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0},
    {.q = 370,
     .description = KERF_TR_NOOP("Maximum path overlap factor"),
     .unit = Unit::Factor,
     .min = 0.1,
     .max = 1.9999,
     .defaultValue = 1.0},
    {.q = 207,
     .description = KERF_TR_NOOP("Feed rate for milling"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 500.0,
     .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth},
    {.q = 385,
     .description = KERF_TR_NOOP("Feed rate for finishing"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 500.0,
     .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth},
    kPrePositionFeed,
    kSetUpClearance,
    {.q = 357,
     .description = KERF_TR_NOOP("Lateral clearance to the workpiece"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 2.0},
    kSecondClearance,
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double top = v.number(227);
    const double bottom = v.number(386);
    if (top == bottom) return std::nullopt;  // depth 0: not executed
    if (top < bottom) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the starting point Q227 must be above the end "
                                       "point Q386"),
                          {"232"}};
    }
    const double cutter = ctx.tool.radius - std::max(0.0, ctx.tool.radius2);
    if (cutter <= 0.0) {
        return CycleError{
            "cycle-tool", KERF_TR_NOOP("cycle {1} needs a tool radius R greater than R2"), {"232"}};
    }
    // Depth levels: equal roughing infeeds, then the finishing pass.
    const double allowance = std::min(v.number(369), top - bottom);
    const double rough = top - bottom - allowance;
    std::vector<double> levels;
    if (rough > 1e-9) {
        const double maxInfeed = v.number(202) > 0.0 ? v.number(202) : rough;
        const double n = std::ceil(rough / maxInfeed - 1e-9);
        if (n > static_cast<double>(kMaxPaths)) return tooManyMoves(232);
        for (int i = 1; i <= static_cast<int>(n); ++i)
            levels.push_back(top - rough * i / n);
    }
    const bool finishing = allowance > 1e-9;
    if (finishing) levels.push_back(bottom);
    // Paths across the second side.
    const double width = std::fabs(v.number(219));
    const double intervals = std::ceil(width / (v.number(370) * cutter) - 1e-9);
    if (intervals * static_cast<double>(levels.size()) > static_cast<double>(kMaxPaths)) {
        return tooManyMoves(232);
    }
    const int paths = static_cast<int>(intervals) + 1;
    const double step = intervals > 0.0 ? v.number(219) / intervals : 0.0;
    const double du = v.number(218) >= 0.0 ? 1.0 : -1.0;
    const int strategy = v.integer(389);
    const double outside = ctx.tool.radius + v.number(357);
    const double uFirst = v.number(225) - du * outside;
    const double uNear = strategy == 1 ? v.number(225) : uFirst;
    const double uFar = v.number(225) + v.number(218) + (strategy == 1 ? 0.0 : du * outside);
    const double clearance = v.number(200);
    const double second = top + std::max(clearance, v.number(204));
    const Feed prePosition = v.feed(253);

    // Positioning logic to start point 1.
    const Vec3 start1(uFirst, v.number(226), top + clearance);
    if (path.w() > top + v.number(204)) {
        path.rapidUv({start1.x(), start1.y()});
    } else {
        path.rapidW(top + v.number(204));
        path.rapidUv({start1.x(), start1.y()});
    }
    path.rapidW(start1.z());
    bool forward = true;  // order of the paths in this infeed
    for (size_t level = 0; level < levels.size(); ++level) {
        const double w = levels[level];
        const Feed mill = finishing && level + 1 == levels.size() ? v.feed(385) : v.feed(207);
        path.moveW(w, prePosition);
        for (int k = 0; k < paths; ++k) {
            const int j = forward ? k : paths - 1 - k;
            const double vLine = v.number(226) + step * j;
            if (k > 0) {
                if (strategy == 2) {
                    path.moveW(w + clearance, prePosition);
                    path.moveUv({uFirst, vLine}, prePosition);
                    path.moveW(w, prePosition);
                } else {
                    path.moveUv({path.uv().x(), vLine}, strategy == 1 ? mill : prePosition);
                }
            }
            const double uTo =
                strategy == 2 || std::fabs(path.uv().x() - uFar) > 1e-9 ? uFar : uNear;
            path.moveUv({uTo, vLine}, mill);
        }
        forward = !forward;
    }
    path.rapidW(second);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle232{.number = 232,
                                .name = KERF_TR_NOOP("FACE MILLING"),
                                .group = CycleGroup::Special,
                                .parameters = kParameters,
                                .expand = expand};

}  // namespace kerf::cycles
