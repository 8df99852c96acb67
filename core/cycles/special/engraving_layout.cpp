#include "core/cycles/special/engraving_layout.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"

namespace kerf::cycles::engraving {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// The text in font units: baseline of the first line at y = 0, further lines below.
struct SetText {
    std::vector<Stroke> strokes;
    double width = 0.0;  // longest line, from the first character's left to the last's right
    int lines = 1;
};

SetText setText(const std::vector<TextToken>& text, double gap) {
    SetText out;
    const double tabStop = 8.0 * (kSpaceWidth + gap);
    double x = 0.0;
    int line = 0;
    for (const TextToken& t : text) {
        switch (t.kind) {
            case TextToken::Kind::NewLine:
                x = 0.0;
                ++line;
                break;
            case TextToken::Kind::VerticalTab:
                ++line;
                break;
            case TextToken::Kind::Tab:
                x = (std::floor(x / tabStop + 1e-9) + 1.0) * tabStop;
                break;
            case TextToken::Kind::Character: {
                const Glyph& g = *findGlyph(t.code);
                const Vec2 offset(x, -kLineSpacing * line);
                for (const Stroke& s : g.strokes) {
                    Stroke placed;
                    for (const Vec2& p : s)
                        placed.push_back(p + offset);
                    out.strokes.push_back(std::move(placed));
                }
                out.width = std::max(out.width, x + g.width);
                x += g.width + gap;
                break;
            }
        }
    }
    out.lines = line + 1;
    return out;
}

// Reference point Q367 of the text block in font units (0 and 1: bottom left).
Vec2 referencePoint(int reference, double width, double bottom) {
    const double right = width, centre = width / 2.0, top = kCapHeight;
    switch (reference) {
        case 2:
            return {centre, bottom};
        case 3:
            return {right, bottom};
        case 4:
            return {right, top};
        case 5:
            return {centre, top};
        case 6:
            return {0.0, top};
        default:
            return {0.0, bottom};
    }
}

CycleError layoutError(const char* messageTemplate, std::vector<std::string> args = {}) {
    return CycleError{"cycle-text", messageTemplate, std::move(args)};
}

}  // namespace

std::optional<CycleError> layoutText(const std::vector<TextToken>& text, const LayoutParameters& p,
                                     std::vector<Stroke>& out) {
    out.clear();
    const double gap = kGap * (p.spacing != 0.0 ? p.spacing : 1.0);
    SetText set = setText(text, gap);
    if (set.strokes.empty()) return std::nullopt;  // only blanks: nothing to engrave
    double scale = p.height / kCapHeight;
    if (p.height == 0.0) {
        if (p.maxLength <= 0.0) {
            return layoutError(
                KERF_TR_NOOP("cycle 225: with the character height Q513 = 0 the "
                             "text length Q574 must be given"));
        }
        if (set.width <= 0.0) {
            return layoutError(
                KERF_TR_NOOP("cycle 225: the text has no length that Q574 could "
                             "scale"));
        }
        scale = p.maxLength / set.width;
    } else if (p.maxLength > 0.0 && set.width * scale > p.maxLength + 1e-9) {
        return layoutError(KERF_TR_NOOP("cycle 225: the text is {1} mm long, longer than the "
                                        "maximum text length Q574 = {2}"),
                           {formatFixed(set.width * scale, 4), formatFixed(p.maxLength, 4)});
    }
    const double bottom = -kLineSpacing * (set.lines - 1);
    const Vec2 reference = referencePoint(p.reference, set.width, bottom);
    const double angle = p.angleDeg * kDegToRad;

    if (p.arrangement == 0) {
        const double c = std::cos(angle), s = std::sin(angle);
        for (Stroke& stroke : set.strokes) {
            for (Vec2& q : stroke) {
                const Vec2 d = (q - reference) * scale;
                q = p.origin + Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
            }
        }
        out = std::move(set.strokes);
        return std::nullopt;
    }
    if (p.radius <= 0.0) {
        return layoutError(KERF_TR_NOOP("cycle 225: text on a circle needs the radius Q517"));
    }
    // The text is centred on the centre angle Q374 with its baseline on the circle, the tops
    // of the characters outwards and the writing clockwise. Q516 = 1 turns text on the lower
    // half of the circle (centre angle 180..360) so that it reads from below: characters
    // towards the centre, writing counter-clockwise.
    const bool readFromBelow = p.arrangement == 1 && std::sin(angle) < -1e-12;
    const double side = readFromBelow ? -1.0 : 1.0;
    auto onCircle = [&](const Vec2& q) {
        const double theta = angle + side * (set.width / 2.0 - q.x()) * scale / p.radius;
        const double r = p.radius + side * q.y() * scale;
        return Vec2(r * std::cos(theta), r * std::sin(theta));
    };
    const Vec2 centre = p.reference == 0 ? p.origin : p.origin - onCircle(reference);
    for (Stroke& stroke : set.strokes) {
        for (Vec2& q : stroke)
            q = centre + onCircle(q);
    }
    out = std::move(set.strokes);
    return std::nullopt;
}

}  // namespace kerf::cycles::engraving
