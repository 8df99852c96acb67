#pragma once

#include <optional>
#include <vector>

#include "core/cycles/special/engraving_font.h"
#include "core/cycles/special/engraving_text.h"

// Where the strokes of the cycle 225 text go in the working plane: the text set in font units
// (lines 16 units apart, characters kGap apart, scaled by Q514), scaled to the character height
// Q513 (or to the length Q574), then placed on a line rotated by Q374 or on a circle of radius
// Q517, with the reference point Q367 at the tool position of the call.
namespace kerf::cycles::engraving {

struct LayoutParameters {
    Vec2 origin{0.0, 0.0};   // tool position at the call: the reference point Q367
    double height = 0.0;     // Q513 cap height (0: scale to maxLength)
    double spacing = 0.0;    // Q514 factor of the gap between characters (0: 1)
    int arrangement = 0;     // Q516: 0 line, 1 arc (readable), 2 arc (continuous)
    double angleDeg = 0.0;   // Q374: line direction, or centre angle of the text on an arc
    double radius = 0.0;     // Q517 baseline radius on an arc
    int reference = 0;       // Q367 0..6
    double maxLength = 0.0;  // Q574 (0: no limit)
};

// The strokes in working-plane coordinates, in engraving order.
std::optional<CycleError> layoutText(const std::vector<TextToken>& text, const LayoutParameters& p,
                                     std::vector<Stroke>& out);

}  // namespace kerf::cycles::engraving
