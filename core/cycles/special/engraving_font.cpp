// The font of cycle 225, designed for this project on a grid of 10 units cap height. Each entry:
// the character, its width and its strokes written as "x y x y ...", strokes separated by '|'.
// Round shapes are polygons with 2-unit corners, which the engraving tool smooths anyway.
#include "core/cycles/special/engraving_font.h"

#include <charconv>
#include <map>
#include <string_view>

namespace kerf::cycles::engraving {

namespace {

struct GlyphText {
    char32_t code;
    double width;
    const char* strokes;
};

// Lower-case umlauts add two dots above the x-height, upper-case ones above the cap height.
#define KERF_LOWER_DOTS "|2 9|4 9"
#define KERF_UPPER_DOTS "|2 12|5 12"
#define KERF_O_UPPER "2 0 0 2 0 8 2 10 5 10 7 8 7 2 5 0 2 0"
#define KERF_A_LOWER "6 7 6 0|6 5 4 7 2 7 0 5 0 2 2 0 4 0 6 2"
#define KERF_O_LOWER "2 0 0 2 0 5 2 7 4 7 6 5 6 2 4 0 2 0"
#define KERF_U_UPPER "0 10 0 2 2 0 5 0 7 2 7 10"
#define KERF_U_LOWER "0 7 0 2 2 0 4 0 6 2|6 7 6 0"

constexpr GlyphText kGlyphs[] = {
    {U' ', kSpaceWidth, ""},
    // Upper case.
    {U'A', 8, "0 0 4 10 8 0|2 5 6 5"},
    {U'B', 7, "0 0 0 10 5 10 7 8 5 5 0 5|5 5 7 3 7 2 5 0 0 0"},
    {U'C', 7, "7 8 5 10 2 10 0 8 0 2 2 0 5 0 7 2"},
    {U'D', 7, "0 0 0 10 4 10 7 7 7 3 4 0 0 0"},
    {U'E', 6, "6 10 0 10 0 0 6 0|0 5 4 5"},
    {U'F', 6, "6 10 0 10 0 0|0 5 4 5"},
    {U'G', 7, "7 8 5 10 2 10 0 8 0 2 2 0 5 0 7 2 7 5 4 5"},
    {U'H', 7, "0 0 0 10|7 0 7 10|0 5 7 5"},
    {U'I', 0, "0 0 0 10"},
    {U'J', 6, "6 10 6 2 4 0 2 0 0 2"},
    {U'K', 7, "0 0 0 10|7 10 0 3|2 5 7 0"},
    {U'L', 6, "0 10 0 0 6 0"},
    {U'M', 8, "0 0 0 10 4 4 8 10 8 0"},
    {U'N', 7, "0 0 0 10 7 0 7 10"},
    {U'O', 7, KERF_O_UPPER},
    {U'P', 7, "0 0 0 10 5 10 7 8 7 7 5 5 0 5"},
    {U'Q', 7, KERF_O_UPPER "|4 3 7 0"},
    {U'R', 7, "0 0 0 10 5 10 7 8 7 7 5 5 0 5|4 5 7 0"},
    {U'S', 7, "7 8 5 10 2 10 0 8 0 7 2 5 5 5 7 3 7 2 5 0 2 0 0 2"},
    {U'T', 8, "0 10 8 10|4 10 4 0"},
    {U'U', 7, KERF_U_UPPER},
    {U'V', 8, "0 10 4 0 8 10"},
    {U'W', 10, "0 10 2 0 5 7 8 0 10 10"},
    {U'X', 7, "0 0 7 10|0 10 7 0"},
    {U'Y', 8, "0 10 4 5 8 10|4 5 4 0"},
    {U'Z', 7, "0 10 7 10 0 0 7 0"},
    // Lower case.
    {U'a', 6, KERF_A_LOWER},
    {U'b', 6, "0 10 0 0|0 5 2 7 4 7 6 5 6 2 4 0 2 0 0 2"},
    {U'c', 6, "6 5 4 7 2 7 0 5 0 2 2 0 4 0 6 2"},
    {U'd', 6, "6 10 6 0|6 5 4 7 2 7 0 5 0 2 2 0 4 0 6 2"},
    {U'e', 6, "0 4 6 4 6 5 4 7 2 7 0 5 0 2 2 0 5 0"},
    {U'f', 4, "4 10 2 10 1 9 1 0|0 7 4 7"},
    {U'g', 6, "6 7 6 -1 4 -3 1 -3|6 5 4 7 2 7 0 5 0 2 2 0 4 0 6 2"},
    {U'h', 6, "0 10 0 0|0 5 2 7 4 7 6 5 6 0"},
    {U'i', 0, "0 0 0 7|0 9"},
    {U'j', 2, "2 7 2 -2 1 -3 0 -3|2 9"},
    {U'k', 6, "0 10 0 0|6 7 0 1|2 3 6 0"},
    {U'l', 1, "0 10 0 1 1 0"},
    {U'm', 10, "0 0 0 7|0 5 2 7 3 7 5 5 5 0|5 5 7 7 8 7 10 5 10 0"},
    {U'n', 6, "0 0 0 7|0 5 2 7 4 7 6 5 6 0"},
    {U'o', 6, KERF_O_LOWER},
    {U'p', 6, "0 7 0 -3|0 5 2 7 4 7 6 5 6 2 4 0 2 0 0 2"},
    {U'q', 6, "6 7 6 -3|6 5 4 7 2 7 0 5 0 2 2 0 4 0 6 2"},
    {U'r', 5, "0 0 0 7|0 5 2 7 5 7"},
    {U's', 6, "6 6 5 7 1 7 0 6 0 5 1 4 5 3 6 2 6 1 5 0 1 0 0 1"},
    {U't', 4, "1 10 1 1 2 0 4 0|0 7 4 7"},
    {U'u', 6, KERF_U_LOWER},
    {U'v', 6, "0 7 3 0 6 7"},
    {U'w', 8, "0 7 2 0 4 5 6 0 8 7"},
    {U'x', 6, "0 0 6 7|0 7 6 0"},
    {U'y', 6, "0 7 3 1|6 7 1 -3 0 -3"},
    {U'z', 6, "0 7 6 7 0 0 6 0"},
    // Digits.
    {U'0', 6, "2 0 0 2 0 8 2 10 4 10 6 8 6 2 4 0 2 0"},
    {U'1', 5, "1 8 3 10 3 0|1 0 5 0"},
    {U'2', 6, "0 8 2 10 4 10 6 8 6 6 0 0 6 0"},
    {U'3', 6, "0 8 2 10 4 10 6 8 6 7 4 5 2 5|4 5 6 3 6 2 4 0 2 0 0 2"},
    {U'4', 6, "5 0 5 10 0 3 6 3"},
    {U'5', 6, "6 10 0 10 0 6 4 6 6 4 6 2 4 0 0 0"},
    {U'6', 6, "6 8 4 10 2 10 0 8 0 2 2 0 4 0 6 2 6 4 4 6 2 6 0 4"},
    {U'7', 6, "0 10 6 10 2 0"},
    {U'8', 6, "2 5 0 7 0 8 2 10 4 10 6 8 6 7 4 5 2 5 0 3 0 2 2 0 4 0 6 2 6 3 4 5"},
    {U'9', 6, "0 2 2 0 4 0 6 2 6 8 4 10 2 10 0 8 0 6 2 4 4 4 6 6"},
    // Special characters of the spec.
    {U'!', 0, "0 10 0 3|0 0"},
    {U'#', 7, "2 0 3 10|4 0 5 10|0 3 7 3|0 7 7 7"},
    {U'$', 6, "6 8 4 9 2 9 0 8 0 6 2 5 4 5 6 4 6 2 4 1 2 1 0 2|3 10 3 0"},
    {U'%', 7, "0 0 7 10|1 10 0 9 1 8 2 9 1 10|6 2 5 1 6 0 7 1 6 2"},
    {U'&', 7, "7 0 1 7 1 9 2 10 3 10 4 9 4 8 0 3 0 1 1 0 4 0 7 4"},
    {U'\'', 0, "0 10 0 7"},
    {U'(', 3, "3 11 1 9 0 6 0 4 1 1 3 -1"},
    {U')', 3, "0 11 2 9 3 6 3 4 2 1 0 -1"},
    {U'*', 6, "3 8 3 2|0 7 6 3|0 3 6 7"},
    {U'+', 6, "3 8 3 2|0 5 6 5"},
    {U',', 1, "1 1 1 0 0 -2"},
    {U'-', 5, "0 5 5 5"},
    {U'.', 0, "0 0"},
    {U'/', 5, "0 0 5 10"},
    {U':', 0, "0 6|0 0"},
    {U';', 1, "1 6|1 1 1 0 0 -2"},
    {U'<', 6, "6 9 0 5 6 1"},
    {U'=', 6, "0 7 6 7|0 3 6 3"},
    {U'>', 6, "0 9 6 5 0 1"},
    {U'?', 6, "0 8 2 10 4 10 6 8 6 7 3 4 3 2|3 0"},
    {U'@', 10, "7 7 7 4 8 3 9 3 10 5 10 7 8 10 3 10 0 7 0 3 3 0 8 0|7 6 5 7 3 7 2 5 3 3 5 3 7 4"},
    {U'[', 3, "3 11 0 11 0 -1 3 -1"},
    {U'\\', 5, "0 10 5 0"},
    {U']', 3, "0 11 3 11 3 -1 0 -1"},
    {U'_', 7, "0 -2 7 -2"},
    // Characters reached through % escapes.
    {U'\u00DF', 6, "0 0 0 8 2 10 4 10 6 8 6 7 4 5 6 3 6 2 4 0 2 0"},  // ß
    {U'\u00E4', 6, KERF_A_LOWER KERF_LOWER_DOTS},                     // ä
    {U'\u00F6', 6, KERF_O_LOWER KERF_LOWER_DOTS},                     // ö
    {U'\u00FC', 6, KERF_U_LOWER KERF_LOWER_DOTS},                     // ü
    {U'\u00C4', 8, "0 0 4 10 8 0|2 5 6 5|2 12|6 12"},                 // Ä
    {U'\u00D6', 7, KERF_O_UPPER KERF_UPPER_DOTS},                     // Ö
    {U'\u00DC', 7, KERF_U_UPPER KERF_UPPER_DOTS},                     // Ü
    {U'\u00F8', 6, KERF_O_LOWER "|0 -1 6 8"},                         // ø (diameter)
    {kCeMark, 13, "6 10 3 10 0 7 0 3 3 0 6 0|13 10 8 10 8 0 13 0|8 5 12 5"},
};

#undef KERF_LOWER_DOTS
#undef KERF_UPPER_DOTS
#undef KERF_O_UPPER
#undef KERF_A_LOWER
#undef KERF_O_LOWER
#undef KERF_U_UPPER
#undef KERF_U_LOWER

std::vector<Stroke> parseStrokes(std::string_view text) {
    std::vector<Stroke> strokes;
    while (!text.empty()) {
        const size_t bar = text.find('|');
        std::string_view part = text.substr(0, bar);
        std::vector<double> numbers;
        while (!part.empty()) {
            while (!part.empty() && part.front() == ' ')
                part.remove_prefix(1);
            if (part.empty()) break;
            double v = 0.0;
            auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
            if (ec != std::errc()) break;  // the table is fixed: unit tests read every glyph
            numbers.push_back(v);
            part.remove_prefix(static_cast<size_t>(end - part.data()));
        }
        Stroke stroke;
        for (size_t i = 0; i + 1 < numbers.size(); i += 2)
            stroke.emplace_back(numbers[i], numbers[i + 1]);
        if (!stroke.empty()) strokes.push_back(std::move(stroke));
        if (bar == std::string_view::npos) break;
        text.remove_prefix(bar + 1);
    }
    return strokes;
}

const std::map<char32_t, Glyph>& font() {
    static const std::map<char32_t, Glyph> kFont = [] {
        std::map<char32_t, Glyph> glyphs;
        for (const GlyphText& g : kGlyphs)
            glyphs[g.code] = Glyph{g.width, parseStrokes(g.strokes)};
        return glyphs;
    }();
    return kFont;
}

}  // namespace

const Glyph* findGlyph(char32_t code) {
    const auto& glyphs = font();
    auto it = glyphs.find(code);
    return it == glyphs.end() ? nullptr : &it->second;
}

}  // namespace kerf::cycles::engraving
