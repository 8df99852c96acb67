// Obsolete cycle 231 RULED SURFACE (docs/cycles.md, "Obsolete Q-parameter cycles"): the surface
// spanned by four points milled in Q240 straight cuts from the edge 1-2 to the edge 4-3, to and
// fro, each cut joining the points at the same fraction of the edges 1-4 and 2-3. The cycle has
// no set-up clearance parameter: the tool clears the surface by its diameter.
#include <algorithm>
#include <array>
#include <string>

#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/pocket/pocket_parameters.h"

namespace kerf::cycles {

namespace {

using namespace pocket;

constexpr ParameterDescriptor coordinate(uint16_t q, const char* description) {
    return {.q = q,
            .description = description,
            .unit = Unit::Millimetre,
            .min = -kLength,
            .max = kLength,
            .defaultValue = 0.0};
}

constexpr ParameterDescriptor kParameters[] = {
    coordinate(225, KERF_TR_NOOP("Starting point in the 1st axis")),
    coordinate(226, KERF_TR_NOOP("Starting point in the 2nd axis")),
    coordinate(227, KERF_TR_NOOP("Starting point in the 3rd axis")),
    coordinate(228, KERF_TR_NOOP("2nd point in the 1st axis")),
    coordinate(229, KERF_TR_NOOP("2nd point in the 2nd axis")),
    coordinate(230, KERF_TR_NOOP("2nd point in the 3rd axis")),
    coordinate(231, KERF_TR_NOOP("3rd point in the 1st axis")),
    coordinate(232, KERF_TR_NOOP("3rd point in the 2nd axis")),
    coordinate(233, KERF_TR_NOOP("3rd point in the 3rd axis")),
    coordinate(234, KERF_TR_NOOP("4th point in the 1st axis")),
    coordinate(235, KERF_TR_NOOP("4th point in the 2nd axis")),
    coordinate(236, KERF_TR_NOOP("4th point in the 3rd axis")),
    {.q = 240,
     .description = KERF_TR_NOOP("Number of cuts"),
     .min = 1.0,
     .max = 99999.0,
     .defaultValue = 5.0,
     .integer = true},
    kMillingFeed,
};

Vec3 point(const CycleValues& v, uint16_t first) {
    return {v.number(first), v.number(static_cast<uint16_t>(first + 1)),
            v.number(static_cast<uint16_t>(first + 2))};
}

// Half a feed (rapid stays rapid).
Feed half(Feed f) {
    if (!f.isRapid()) f.value /= 2.0;
    return f;
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const std::array<Vec3, 4> p = {point(v, 225), point(v, 228), point(v, 231), point(v, 234)};
    const double clearance = 2.0 * ctx.tool.radius;
    const double top = std::max({p[0].z(), p[1].z(), p[2].z(), p[3].z()}) + clearance;
    const int cuts = v.integer(240);
    const Feed feed = v.feed(207);
    // The old manuals: the first step at half the milling feed (the tool cuts with its whole
    // width); here the move onto point 1 and the first cut.
    const Feed firstFeed = half(feed);
    // Up to the tool diameter above the highest point, over point 1, down to the tool diameter
    // above it at rapid and onto it.
    if (path.w() < top) path.rapidW(top);
    path.rapidUv({p[0].x(), p[0].y()});
    path.rapidW(p[0].z() + clearance);
    path.move(p[0], firstFeed);
    for (int k = 0; k < cuts; ++k) {
        if (path.limitReached()) return tooManyMoves(231);
        const double t = cuts > 1 ? static_cast<double>(k) / (cuts - 1) : 0.0;
        const Vec3 a = p[0] + t * (p[3] - p[0]);
        const Vec3 b = p[1] + t * (p[2] - p[1]);
        const bool forward = k % 2 == 0;
        path.move(forward ? a : b, feed);  // the stepover along the edge (none for the first)
        path.move(forward ? b : a, k == 0 ? firstFeed : feed);
    }
    path.rapidW(top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle231{.number = 231,
                                .name = KERF_TR_NOOP("RULED SURFACE"),
                                .group = CycleGroup::Special,
                                .parameters = kParameters,
                                .expand = expand,
                                .obsolete = true};

}  // namespace kerf::cycles
