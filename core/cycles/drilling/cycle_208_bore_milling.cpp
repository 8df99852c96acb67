// Cycle 208 BORE MILLING (spec §2): a half-circle approach from the hole centre to the diameter
// at set-up clearance, a helix of pitch Q334 (limited by the tool's plunge ANGLE) from there to
// the depth, one full circle at the depth, back to the centre, retract at rapid.
#include <cmath>
#include <numbers>

#include "core/base/fixed_format.h"
#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

constexpr ParameterDescriptor kParameters[] = {
    kSetUpClearance,
    kDepth,
    {.q = 206,
     .description = KERF_TR_NOOP("Feed rate for helical drilling"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 150.0,
     .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth},
    {.q = 334,
     .description = KERF_TR_NOOP("Infeed per helix revolution"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.25},
    kSurface,
    kSecondClearance,
    kNominalDiameter,
    {.q = 342,
     .description = KERF_TR_NOOP("Roughing (pre-drilled) diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0},
    addedLater(kClimbOrUpCut),
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double signedDepth = v.number(201);
    if (signedDepth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(208, 201, signedDepth, ctx)) return e;
    const double toolDiameter = 2.0 * ctx.tool.radius;
    const double diameter = v.number(335);
    if (diameter < toolDiameter - 1e-9) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1}: the nominal diameter {2} is smaller than the "
                                       "tool diameter {3}"),
                          {"208", formatFixed(diameter, 4), formatFixed(toolDiameter, 4)}};
    }
    if (v.number(342) == 0.0 && toolDiameter > 0.0 && diameter > 2.0 * toolDiameter) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1}: the nominal diameter is more than twice the "
                                       "tool diameter; enter the roughing diameter Q342"),
                          {"208"}};
    }
    const HoleLevels l = holeLevels(v, signedDepth);
    const double bottom = l.at(std::fabs(signedDepth));
    const Vec2 centre = path.uv();
    const Feed feed = v.feed(206);
    const double rho = (diameter - toolDiameter) / 2.0;
    if (rho <= 1e-4) {
        path.rapidW(l.clearance);
        // Tool diameter = hole diameter: plain plunge, no helix.
        path.moveW(bottom, feed);
        path.rapidW(l.clearance);
        path.rapidW(l.top);
        return std::nullopt;
    }
    double pitch = v.number(334);
    if (ctx.tool.plungeAngleDeg > 0.0) {
        pitch = std::min(
            pitch, kTwoPi * rho * std::tan(ctx.tool.plungeAngleDeg * std::numbers::pi / 180.0));
    }
    if (pitch <= 0.0) {
        return CycleError{"cycle-parameter",
                          KERF_TR_NOOP("cycle {1}: the infeed per helix Q334 must be greater "
                                       "than 0"),
                          {"208"}};
    }
    const double travel = std::fabs(l.clearance - bottom);
    const double turns = travel / pitch;
    if (turns > static_cast<double>(CyclePath::kMoveLimit)) return tooManyMoves(208);
    path.rapidW(l.clearance);
    // Climb milling with M3 runs counter-clockwise in a hole; a mirror image keeps the type.
    bool ccw = v.integer(351) >= 0;
    if (ctx.mirroredMain != ctx.mirroredSecondary) ccw = !ccw;
    const double dir = ccw ? 1.0 : -1.0;
    const Vec2 contact = centre + Vec2(rho, 0.0);
    path.arc({contact.x(), contact.y(), l.clearance}, centre + Vec2(rho / 2.0, 0.0),
             dir * std::numbers::pi, feed);
    const auto whole = static_cast<size_t>(std::floor(turns + 1e-9));
    double w = l.clearance;
    const double rest = turns - static_cast<double>(whole);
    for (size_t i = 0; i < whole; ++i) {
        // The last whole turn ends exactly at the depth when no part turn follows.
        w = (i + 1 == whole && rest <= 1e-9) ? bottom : w - l.up * pitch;
        path.arc({contact.x(), contact.y(), w}, centre, dir * kTwoPi, feed);
    }
    Vec2 end = contact;
    if (rest > 1e-9) {
        const double angle = dir * kTwoPi * rest;
        end = centre + rho * Vec2(std::cos(angle), std::sin(angle));
        path.arc({end.x(), end.y(), bottom}, centre, angle, feed);
    }
    path.arc({end.x(), end.y(), bottom}, centre, dir * kTwoPi, feed);
    path.moveUv(centre, feed);
    path.rapidW(l.clearance);
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle208{.number = 208,
                                .name = KERF_TR_NOOP("BORE MILLING"),
                                .group = CycleGroup::Drilling,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
