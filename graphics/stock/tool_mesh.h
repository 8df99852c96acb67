#pragma once

#include "graphics/stock/cutter.h"
#include "graphics/stock/mesh.h"

namespace kerf::graphics {

// Solid of a milling tool, tip at the origin, pointing down the tool axis (Z: the tool stands
// on +Z; X, Y: it lies along +X, +Y). Shown length: cutter.lengthMm or four radii (>= 10 mm).
Mesh millToolMesh(const MillCutter& cutter, Axis axis = Axis::Z, int segments = 32);
// A lathe insert in the plane Y = 0 (X radius, Z), programmed point at the origin, as a plate
// of the given thickness.
Mesh latheInsertMesh(const LatheInsert& insert, double thicknessMm = 1.0);

}  // namespace kerf::graphics
