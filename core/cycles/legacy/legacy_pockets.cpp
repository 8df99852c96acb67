// Legacy cycles 4 POCKET MILLING and 5 CIRCULAR POCKET (docs/cycles.md): roughing a pocket
// centred where the tool stands, run as cycles 251 and 252 with roughing only, no allowances,
// a vertical plunge and the direction DR+ (counterclockwise: climb milling with M3) or DR-.
#include <cmath>

#include "core/cycles/legacy/legacy_list.h"

namespace kerf::cycles {

namespace {

using namespace legacy;

constexpr ParameterDescriptor kPlungeFeed{
    .word = "F",
    .description = KERF_TR_NOOP("Feed rate for plunging (none: the milling feed)"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = 99999.0,
    .optional = true};
constexpr ParameterDescriptor kDirection{
    .word = "DR",
    .description = KERF_TR_NOOP("Direction: DR+ counterclockwise, DR- clockwise"),
    .unit = Unit::None,
    .min = -1.0,
    .max = 1.0,
    .defaultValue = 1.0,
    .optional = true};

// What both pockets set alike: roughing only, no allowances, the depth and its infeeds, the
// feeds and the direction, the levels from the start.
CycleValues roughing(const CycleDescriptor& modern, const CycleValues& v, uint16_t feedId,
                     uint16_t directionId, double start) {
    CycleValues m = defaultsOf(modern);
    const Feed mill = v.feed(feedId);
    const Feed plunge = v.has(4) && !v.feed(4).isZero() ? v.feed(4) : mill;
    m.set(215, 1.0);
    m.set(368, 0.0);
    m.set(369, 0.0);
    m.set(338, 0.0);
    m.set(366, 0.0);
    m.set(201, v.number(2));
    m.set(202, std::fabs(v.number(3)));
    m.setFeed(207, mill);
    m.setFeed(385, mill);
    m.setFeed(206, plunge);
    m.set(351, v.number(directionId) < 0.0 ? -1.0 : 1.0);
    setStartLevels(m, start, v.number(1), v.number(2));
    return m;
}

constexpr ParameterDescriptor kPocketParameters[] = {
    kSetUp,
    kLegacyDepth,
    kPeckingDepth,
    kPlungeFeed,
    {.word = "X",
     .description = KERF_TR_NOOP("First side length (parallel to the first axis)"),
     .unit = Unit::Millimetre,
     .min = -kMaxLength,
     .max = kMaxLength},
    {.word = "Y",
     .description = KERF_TR_NOOP("Second side length"),
     .unit = Unit::Millimetre,
     .min = -kMaxLength,
     .max = kMaxLength},
    kFeed,
    kDirection,
    {.word = "RADIUS",
     .description = KERF_TR_NOOP("Corner radius"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kMaxLength,
     .optional = true},
};

std::optional<CycleError> expandPocket(const CycleValues& v, const CycleContext& ctx,
                                       CyclePath& path) {
    if (v.number(2) == 0.0) return std::nullopt;
    CycleValues m = roughing(kCycle251, v, 7, 8, ctx.start.z());
    m.set(218, std::fabs(v.number(5)));
    m.set(219, std::fabs(v.number(6)));
    m.set(220, v.number(9));
    m.set(224, 0.0);
    m.set(367, 0.0);  // the pocket's centre is the start
    return expandAs(4, kCycle251, m, ctx, path);
}

constexpr ParameterDescriptor kCircularPocketParameters[] = {
    kSetUp,
    kLegacyDepth,
    kPeckingDepth,
    kPlungeFeed,
    {.word = "RADIUS",
     .description = KERF_TR_NOOP("Pocket radius"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kMaxLength},
    kFeed,
    kDirection,
};

std::optional<CycleError> expandCircularPocket(const CycleValues& v, const CycleContext& ctx,
                                               CyclePath& path) {
    if (v.number(2) == 0.0) return std::nullopt;
    CycleValues m = roughing(kCycle252, v, 6, 7, ctx.start.z());
    m.set(223, 2.0 * v.number(5));
    return expandAs(5, kCycle252, m, ctx, path);
}

}  // namespace

const CycleDescriptor kCycle4{.number = 4,
                              .name = KERF_TR_NOOP("POCKET MILLING"),
                              .group = CycleGroup::PocketsStudsSlots,
                              .oldStyle = true,
                              .parameters = kPocketParameters,
                              .expand = expandPocket};
const CycleDescriptor kCycle5{.number = 5,
                              .name = KERF_TR_NOOP("CIRCULAR POCKET"),
                              .group = CycleGroup::PocketsStudsSlots,
                              .oldStyle = true,
                              .parameters = kCircularPocketParameters,
                              .expand = expandCircularPocket};

}  // namespace kerf::cycles
