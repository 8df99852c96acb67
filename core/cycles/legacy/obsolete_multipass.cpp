// Obsolete cycle 230 MULTIPASS MILLING (docs/cycles.md, "Obsolete Q-parameter cycles"): a flat
// rectangle at the height Q227 milled in Q240 parallel cuts along the 1st axis, to and fro.
#include <cmath>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 225,
     .description = KERF_TR_NOOP("Starting point in the 1st axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    {.q = 226,
     .description = KERF_TR_NOOP("Starting point in the 2nd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    {.q = 227,
     .description = KERF_TR_NOOP("Starting point in the 3rd axis (surface)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    kFirstSide,
    kSecondSide,
    {.q = 240,
     .description = KERF_TR_NOOP("Number of cuts"),
     .min = 1.0,
     .max = 99999.0,
     .defaultValue = 5.0,
     .integer = true},
    {.q = 206,
     .description = KERF_TR_NOOP("Feed rate to the starting point in the tool axis"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 150.0,
     .keywords = kFeedMax | kFeedAuto | kFeedPerRev | kFeedPerTooth},
    kMillingFeed,
    {.q = 209,
     .description = KERF_TR_NOOP("Feed rate for stepover (FMAX: rapid)"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 200.0,
     .keywords = kFeedMax | kFeedAuto | kFeedPerRev | kFeedPerTooth},
    common::kSetUpClearance,
};

// The cuts run from R before the rectangle's start edge to R beyond its end edge, so the tool
// enters and leaves it completely; the first cut on the 2nd axis' starting point, the last on
// the far side, the others evenly between.
std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double r = ctx.tool.radius;
    const double height = v.number(227);
    const double clearance = height + v.number(200);
    const int cuts = v.integer(240);
    const double step = cuts > 1 ? v.number(219) / (cuts - 1) : 0.0;
    const double from = v.number(225) - r;
    const double to = v.number(225) + v.number(218) + r;
    path.rapidUv({from, v.number(226)});
    path.rapidW(clearance);
    path.moveW(height, v.feed(206));
    for (int k = 0; k < cuts; ++k) {
        if (path.limitReached()) return tooManyMoves(230);
        const double y = v.number(226) + k * step;
        if (k > 0) path.moveUv({path.uv().x(), y}, v.feed(209));
        path.moveUv({k % 2 == 0 ? to : from, y}, v.feed(207));
    }
    path.rapidW(clearance);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle230{.number = 230,
                                .name = KERF_TR_NOOP("MULTIPASS MILLING"),
                                .group = CycleGroup::Special,
                                .parameters = kParameters,
                                .expand = expand,
                                .obsolete = true};

}  // namespace kerf::cycles
