// Legacy cycle 3 SLOT MILLING (docs/cycles.md, "Cycles of older TNCs"): a straight slot of
// rectangular outline that starts where the tool stands (the middle of its width, the tool
// radius inside its first end). The old manuals' sequence: roughing along the slot's middle,
// the milling allowance (half the width less the tool radius) away from both ends, to and fro
// with an infeed at each end; then at the bottom a tangential arc onto the wall path and once
// round it counter-clockwise (climb milling with M3); up to the set-up clearance, and back to
// the start when the number of infeeds was odd.
#include <cmath>
#include <numbers>
#include <vector>

#include "core/cycles/cycle_path.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/legacy/legacy_list.h"
#include "core/cycles/pocket/milling_setup.h"

namespace kerf::cycles {

namespace {

using namespace legacy;

constexpr ParameterDescriptor kSlotParameters[] = {
    kSetUp,
    kLegacyDepth,
    kPeckingDepth,
    {.word = "F",
     .description = KERF_TR_NOOP("Feed rate for plunging (none: the milling feed)"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = 99999.0,
     .optional = true},
    {.word = "X",
     .description = KERF_TR_NOOP("First side length (parallel to the first axis)"),
     .unit = Unit::Millimetre,
     .min = -kMaxLength,
     .max = kMaxLength},
    {.word = "AXIS",
     .description = KERF_TR_NOOP("Axis of the first side length: 0 main axis, 1 secondary axis"),
     .unit = Unit::None,
     .min = 0.0,
     .max = 1.0,
     .optional = true},
    {.word = "Y",
     .description = KERF_TR_NOOP("Second side length"),
     .unit = Unit::Millimetre,
     .min = -kMaxLength,
     .max = kMaxLength},
    kFeed,
};

CycleError slotError(const char* code, const char* message) {
    return CycleError{code, message, {"3"}};
}

std::optional<CycleError> expandSlot(const CycleValues& v, const CycleContext& ctx,
                                     CyclePath& path) {
    const double depth = v.number(2);
    if (depth == 0.0) return std::nullopt;
    const double radius = ctx.tool.radius;
    const double width = std::fabs(v.number(7));
    const double length = std::fabs(v.number(5));
    if (radius <= 0.0) {
        return slotError("cycle-tool",
                         KERF_TR_NOOP("cycle {1} needs a tool with a radius greater than 0"));
    }
    if (2.0 * radius > width + 1e-9) return pocket::toolTooLarge(3);
    if (4.0 * radius < width - 1e-9) {
        return slotError("cycle-tool", KERF_TR_NOOP("cycle {1}: the tool diameter must be at "
                                                    "least half the slot width"));
    }
    if (length < width - 1e-9) {
        return slotError("cycle-geometry",
                         KERF_TR_NOOP("cycle {1}: the slot is shorter than it is wide"));
    }
    std::vector<double> infeeds;
    if (auto e = planInfeeds(3, std::fabs(depth), std::fabs(v.number(3)), 0.0, 0.0, infeeds))
        return e;

    // The slot's frame: p along it from the start (its direction the sign of the length, along
    // the main or the secondary axis), q across it, turned counter-clockwise from p.
    const double sign = v.number(5) < 0.0 ? -1.0 : 1.0;
    const Vec2 along = v.number(6) > 0.5 ? Vec2{0.0, sign} : Vec2{sign, 0.0};
    const Vec2 across{-along.y(), along.x()};
    const Vec2 start{ctx.start.x(), ctx.start.y()};
    auto at = [&](double p, double q) -> Vec2 { return start + p * along + q * across; };

    const double allowance = width / 2.0 - radius;  // the milling allowance
    const double end = length - 2.0 * radius;       // the tool centre's far end
    const double up = depth < 0.0 ? 1.0 : -1.0;     // w away from the material
    const double surface = ctx.start.z() - up * std::fabs(v.number(1));
    const Feed mill = v.feed(8);
    const Feed plunge = v.has(4) && !v.feed(4).isZero() ? v.feed(4) : mill;

    // Roughing: to and fro between the allowance from each end, an infeed at each end.
    double p = allowance;
    path.rapidUv(at(p, 0.0));
    for (double infeed : infeeds) {
        path.moveW(surface - up * infeed, plunge);
        p = p == allowance ? end - allowance : allowance;
        path.moveUv(at(p, 0.0), mill);
    }
    // Finishing: a half circle of half the allowance onto the middle of the end wall's path,
    // once round counter-clockwise, the mirror half circle back.
    if (allowance > 1e-9) {
        const bool far = p != allowance;
        const double wall = far ? end : 0.0;
        const double toward = far ? 1.0 : -1.0;  // from the roughing end to its wall
        const Vec2 centre = at(wall - toward * allowance / 2.0, 0.0);
        const double half = std::numbers::pi;
        const Vec2 onWall = at(wall, 0.0);
        path.arc({onWall.x(), onWall.y(), path.w()}, centre, half, mill);
        const double q = toward * allowance;  // the side the counter-clockwise path goes to
        const Vec2 corners[] = {at(wall, q), at(end - wall, q), at(end - wall, -q), at(wall, -q),
                                onWall};
        for (const Vec2& c : corners)
            path.moveUv(c, mill);
        const Vec2 back = at(p, 0.0);
        path.arc({back.x(), back.y(), path.w()}, centre, half, mill);
    }
    path.rapidW(ctx.start.z());
    if (infeeds.size() % 2 == 1) path.rapidUv(start);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle3{.number = 3,
                              .name = KERF_TR_NOOP("SLOT MILLING"),
                              .group = CycleGroup::PocketsStudsSlots,
                              .oldStyle = true,
                              .parameters = kSlotParameters,
                              .expand = expandSlot};

}  // namespace kerf::cycles
