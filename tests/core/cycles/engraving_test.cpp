// Cycle 225: the font covers the characters the spec permits, the text escapes decode as the
// spec lists them (with a fixed clock), and the layout places the font's strokes by scale,
// reference point, rotation and arc as derived by hand in the comments.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/cycles/special/engraving_layout.h"

namespace kerf::cycles::engraving {
namespace {

constexpr double kTol = 1e-9;

std::u32string decoded(const std::string& text, unsigned long long counter = 0) {
    const DateTime now{2026, 3, 7, 9, 5, 4};
    std::vector<TextToken> tokens;
    auto error = decodeText(text, now, counter, tokens);
    EXPECT_FALSE(error) << text << ": " << (error ? error->messageTemplate : "");
    std::u32string out;
    for (const TextToken& t : tokens) {
        out += t.kind == TextToken::Kind::NewLine       ? U'\n'
               : t.kind == TextToken::Kind::Tab         ? U'\t'
               : t.kind == TextToken::Kind::VerticalTab ? U'\v'
                                                        : t.code;
    }
    return out;
}

bool refused(const std::string& text) {
    std::vector<TextToken> tokens;
    auto error = decodeText(text, DateTime{}, 0, tokens);
    return error && error->code == "cycle-text";
}

std::vector<Stroke> laidOut(const std::string& text, const LayoutParameters& p) {
    std::vector<TextToken> tokens;
    EXPECT_FALSE(decodeText(text, DateTime{}, 0, tokens));
    std::vector<Stroke> strokes;
    auto error = layoutText(tokens, p, strokes);
    EXPECT_FALSE(error) << (error ? error->messageTemplate : "");
    return strokes;
}

void expectPoint(const Vec2& actual, double x, double y) {
    EXPECT_NEAR(actual.x(), x, 1e-9);
    EXPECT_NEAR(actual.y(), y, 1e-9);
}

TEST(EngravingFont, CoversEveryPermittedCharacter) {
    std::u32string all = U"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    all += U"!#$%&'()*+,-./:;<=>?@[\\]_";
    all += U"\u00DF\u00E4\u00F6\u00FC\u00C4\u00D6\u00DC\u00F8";
    all += kCeMark;
    for (char32_t c : all) {
        const Glyph* g = findGlyph(c);
        ASSERT_NE(g, nullptr) << static_cast<unsigned>(c);
        EXPECT_FALSE(g->strokes.empty()) << static_cast<unsigned>(c);
        for (const Stroke& s : g->strokes) {
            for (const Vec2& p : s) {
                // Inside the character's cell: its width, descender to above the cap height.
                EXPECT_GE(p.x(), -kTol) << static_cast<unsigned>(c);
                EXPECT_LE(p.x(), g->width + kTol) << static_cast<unsigned>(c);
                EXPECT_GE(p.y(), kDescender - kTol) << static_cast<unsigned>(c);
                EXPECT_LE(p.y(), kCapHeight + 2.0 + kTol) << static_cast<unsigned>(c);
            }
        }
    }
    const Glyph* space = findGlyph(U' ');
    ASSERT_NE(space, nullptr);
    EXPECT_TRUE(space->strokes.empty());
    EXPECT_EQ(findGlyph(U'~'), nullptr);
    EXPECT_EQ(findGlyph(U'"'), nullptr);
}

TEST(EngravingFont, LetterLIsTheDefinedStroke) {
    const Glyph* l = findGlyph(U'L');
    ASSERT_NE(l, nullptr);
    EXPECT_EQ(l->width, 6.0);
    ASSERT_EQ(l->strokes.size(), 1u);
    ASSERT_EQ(l->strokes[0].size(), 3u);
    expectPoint(l->strokes[0][0], 0, 10);
    expectPoint(l->strokes[0][1], 0, 0);
    expectPoint(l->strokes[0][2], 6, 0);
}

TEST(EngravingText, EscapesFromTheSpec) {
    EXPECT_EQ(decoded("A%%B"), U"A%B");
    EXPECT_EQ(decoded("A\\\\B"), U"A\\B");
    EXPECT_EQ(decoded("%ae%oe%ue%AE%OE%UE%ss"), U"\u00E4\u00F6\u00FC\u00C4\u00D6\u00DC\u00DF");
    EXPECT_EQ(decoded("%D10"),
              U"\u00F8"
              U"10");
    EXPECT_EQ(decoded("a%atb"), U"a@b");
    EXPECT_EQ(decoded("%CE"), std::u32string(1, kCeMark));
    EXPECT_EQ(decoded("A\\nB\\tC\\vD"), U"A\nB\tC\vD");
    EXPECT_EQ(decoded("Stra\xC3\x9F"
                      "e"),
              U"Stra\u00DFe");  // UTF-8 ß written directly
}

TEST(EngravingText, TimeAndCounterWithAFixedClock) {
    // 7 March 2026, 09:05:04.
    EXPECT_EQ(decoded("%time00"), U"07.03.2026 09:05:04");
    EXPECT_EQ(decoded("%time01"), U"7.03.2026 9:05:04");
    EXPECT_EQ(decoded("%time03"), U"7.03.26 9:05");
    EXPECT_EQ(decoded("%time04"), U"2026-03-07 09:05:04");
    EXPECT_EQ(decoded("%time07"), U"26-03-07 9:05");
    EXPECT_EQ(decoded("%time08"), U"07.03.2026");
    EXPECT_EQ(decoded("%time10"), U"7.03.26");
    EXPECT_EQ(decoded("%time12"), U"26-03-07");
    EXPECT_EQ(decoded("%time13"), U"09:05:04");
    EXPECT_EQ(decoded("%time15"), U"9:05");
    EXPECT_EQ(decoded("N%count3"), U"N000");  // test run: the counter is 0
    EXPECT_EQ(decoded("%count9", 3), U"000000003");
}

TEST(EngravingText, UnknownInputIsRefused) {
    EXPECT_TRUE(refused("A~B"));
    EXPECT_TRUE(refused("%xy"));
    EXPECT_TRUE(refused("%time16"));
    EXPECT_TRUE(refused("%time8"));
    EXPECT_TRUE(refused("%count"));
    EXPECT_TRUE(refused("\\q"));
    EXPECT_TRUE(refused("50%"));
}

TEST(EngravingLayout, ReferencePointAndRotation) {
    LayoutParameters p;
    p.origin = {100, 50};
    p.height = 20;    // scale 2
    p.reference = 3;  // bottom right: (6, 0) of the L
    auto s = laidOut("L", p);
    ASSERT_EQ(s.size(), 1u);
    expectPoint(s[0][0], 100 - 12, 50 + 20);
    expectPoint(s[0][1], 100 - 12, 50);
    expectPoint(s[0][2], 100, 50);

    // 180 degrees: the writing runs backwards, (x, y) -> (-x, -y) about the reference.
    p.angleDeg = 180;
    p.reference = 0;
    s = laidOut("L", p);
    expectPoint(s[0][0], 100, 50 - 20);
    expectPoint(s[0][2], 100 - 12, 50);
}

TEST(EngravingLayout, LinesTabsAndSpacing) {
    LayoutParameters p;
    p.height = 10;
    // Two lines 16 units apart; bottom left is the baseline of the last line.
    auto s = laidOut("I\\nI", p);
    ASSERT_EQ(s.size(), 2u);
    expectPoint(s[0][0], 0, 16);
    expectPoint(s[1][0], 0, 0);
    // A tab goes to 8 x (space 4 + gap 2) = 48.
    s = laidOut("I\\tI", p);
    expectPoint(s[1][0], 48, 0);
    // Q514 = 3 triples the gap: the second I of "II" at 0 + 3 x 2.
    p.spacing = 3;
    s = laidOut("II", p);
    expectPoint(s[1][0], 6, 0);
}

TEST(EngravingLayout, LengthScalingAndLimit) {
    LayoutParameters p;
    p.height = 0;
    p.maxLength = 32;  // "LT" is 16 units: scale 2
    auto s = laidOut("LT", p);
    ASSERT_EQ(s.size(), 3u);
    expectPoint(s[1][0], 16, 20);
    expectPoint(s[1][1], 32, 20);

    std::vector<TextToken> tokens;
    ASSERT_FALSE(decodeText("LT", DateTime{}, 0, tokens));
    std::vector<Stroke> strokes;
    p.maxLength = 0;
    EXPECT_TRUE(layoutText(tokens, p, strokes));  // neither height nor length
    p.height = 10;
    p.maxLength = 15.9;
    EXPECT_TRUE(layoutText(tokens, p, strokes));  // 16 mm > 15.9 mm
    p.maxLength = 16;
    EXPECT_FALSE(layoutText(tokens, p, strokes));
    p.arrangement = 1;
    p.radius = 0;
    EXPECT_TRUE(layoutText(tokens, p, strokes));  // an arc needs its radius
    // "I" is a single stroke without width: there is nothing to scale to a length.
    ASSERT_FALSE(decodeText("I", DateTime{}, 0, tokens));
    p = LayoutParameters{};
    p.maxLength = 10;
    EXPECT_TRUE(layoutText(tokens, p, strokes));
}

TEST(EngravingLayout, ArcReferencePoints) {
    LayoutParameters p;
    p.origin = {10, 10};
    p.height = 10;
    p.arrangement = 1;
    p.radius = 20;
    p.angleDeg = 0;
    // A lone I (width 0) centred at 0 degrees: from radius 20 to 30 along +x.
    auto s = laidOut("I", p);
    expectPoint(s[0][0], 30, 10);
    expectPoint(s[0][1], 40, 10);
    // Reference 5 (top centre) is (0, 10) of the text: radius 30 at 0 degrees, so the centre
    // is 30 to the left of the tool.
    p.reference = 5;
    s = laidOut("I", p);
    expectPoint(s[0][0], 0, 10);
    expectPoint(s[0][1], 10, 10);
    // Continuous text at 270 degrees keeps its tops outwards: the I points down.
    p.reference = 0;
    p.arrangement = 2;
    p.angleDeg = 270;
    s = laidOut("I", p);
    expectPoint(s[0][0], 10, -10);
    expectPoint(s[0][1], 10, -20);
    // Readable text there points towards the centre.
    p.arrangement = 1;
    s = laidOut("I", p);
    expectPoint(s[0][0], 10, -10);
    expectPoint(s[0][1], 10, 0);
}

}  // namespace
}  // namespace kerf::cycles::engraving
