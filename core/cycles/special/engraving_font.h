#pragma once

#include <span>
#include <vector>

#include "core/geometry/axes.h"

// The single-stroke font of cycle 225 ENGRAVING. Every character is a few polylines on a grid
// whose cap height is kCapHeight units: x from 0 to the character's width, y = 0 on the baseline,
// lower-case letters kXHeight high, descenders down to kDescender. The font is proportional:
// each character has its own width and the next one starts kGap units after it.
namespace kerf::cycles::engraving {

inline constexpr double kCapHeight = 10.0;
inline constexpr double kXHeight = 7.0;
inline constexpr double kDescender = -3.0;
inline constexpr double kGap = 2.0;           // between two characters (Q514 = 0)
inline constexpr double kLineSpacing = 16.0;  // baseline to baseline (\n, \v)
inline constexpr double kSpaceWidth = 4.0;

// Code of the CE mark (%CE), which has no character of its own.
inline constexpr char32_t kCeMark = 0xE000;

// One polyline; a single point is a dot (plunge and lift).
using Stroke = std::vector<Vec2>;

struct Glyph {
    double width = 0.0;
    std::vector<Stroke> strokes;
};

// The character, or nullptr when the font has none (the cycle names it in its diagnostic).
const Glyph* findGlyph(char32_t code);

}  // namespace kerf::cycles::engraving
