#pragma once

#include <vector>

#include "core/cycles/lathe/section_turning.h"

namespace kerf::cycles::lathe {

// The raw-stock profile as points in (z, x radius), its arcs as chords at most `chordErrorMm`
// from the arc: the blank's outline the graphics turns about Z.
std::vector<Vec2> rawOutlinePoints(const RawStock& raw, double chordErrorMm);

}  // namespace kerf::cycles::lathe
