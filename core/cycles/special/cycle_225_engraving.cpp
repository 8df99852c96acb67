// Cycle 225 ENGRAVING (spec §10): every stroke of the text is approached at the set-up
// clearance, plunged at Q206 to the depth Q201 and milled at Q207; the tool lifts at rapid to
// the set-up clearance after each stroke and ends at the 2nd set-up clearance.
#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/special/engraving_layout.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 500, .description = KERF_TR_NOOP("Engraving text"), .unit = Unit::Text},
    {.q = 513,
     .description = KERF_TR_NOOP("Character height (0: scaled to the text length Q574)"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 10.0},
    {.q = 514,
     .description = KERF_TR_NOOP("Spacing factor between the characters (0: as the font)"),
     .unit = Unit::Factor,
     .min = 0.0,
     .max = 9.9999},
    {.q = 515,
     .description = KERF_TR_NOOP("Font (without function)"),
     .min = 0.0,
     .max = 99.0,
     .optional = true,
     .integer = true},
    {.q = 516,
     .description = KERF_TR_NOOP("Text on a line (0), an arc (1) or an arc, continuous (2)"),
     .min = 0.0,
     .max = 2.0,
     .integer = true},
    {.q = 374,
     .description = KERF_TR_NOOP("Angle of rotation (centre angle on an arc)"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0},
    {.q = 517,
     .description = KERF_TR_NOOP("Radius of the arc the text is on"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength},
    {.q = 207,
     .description = KERF_TR_NOOP("Feed rate for milling"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed,
     .defaultValue = 500.0,
     .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth},
    kDepth,
    kPlungeFeed,
    kSetUpClearance,
    kSurface,
    kSecondClearance,
    {.q = 367,
     .description = KERF_TR_NOOP("Reference of the text position (0-6)"),
     .min = 0.0,
     .max = 6.0,
     .optional = true,
     .integer = true},
    {.q = 574,
     .description = KERF_TR_NOOP("Maximum text length (0: no limit)"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .optional = true},
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double depth = v.number(201);
    if (depth == 0.0) return std::nullopt;
    if (auto e = checkDepthSign(225, 201, depth, ctx)) return e;

    std::vector<engraving::TextToken> text;
    if (auto e = engraving::decodeText(v.text(500), ctx.now, ctx.counter, text)) return e;
    engraving::LayoutParameters layout;
    layout.origin = {ctx.start.x(), ctx.start.y()};
    layout.height = v.number(513);
    layout.spacing = v.number(514);
    layout.arrangement = v.integer(516);
    layout.angleDeg = v.number(374);
    layout.radius = v.number(517);
    layout.reference = v.integer(367);
    layout.maxLength = v.number(574);
    std::vector<engraving::Stroke> strokes;
    if (auto e = engraving::layoutText(text, layout, strokes)) return e;

    const HoleLevels levels = holeLevels(v, depth);
    const double floor = v.number(203) + depth;
    for (const engraving::Stroke& stroke : strokes) {
        if (path.limitReached()) return std::nullopt;
        // Coming from above the set-up clearance the plane move goes first, else the lift.
        if (levels.up * (path.w() - levels.clearance) > 0.0) {
            path.rapidUv(stroke.front());
            path.rapidW(levels.clearance);
        } else {
            path.rapidW(levels.clearance);
            path.rapidUv(stroke.front());
        }
        path.moveW(floor, v.feed(206));
        for (size_t i = 1; i < stroke.size(); ++i)
            path.moveUv(stroke[i], v.feed(207));
        path.rapidW(levels.clearance);
    }
    path.rapidW(levels.top);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle225{.number = 225,
                                .name = KERF_TR_NOOP("ENGRAVING"),
                                .group = CycleGroup::Special,
                                .parameters = kParameters,
                                .expand = expand,
                                .takesPatternClearances = true};

}  // namespace kerf::cycles
