#pragma once

#include <cstdint>

#include "core/canon/commands.h"

// The serpentine raster of shared/tools/gen_nc.py as canonical commands (same geometry, made
// directly so the motion tests do not depend on an interpreter): rows of 99 short linear moves
// of `segMm` along +-X over z = -1 + 0.5 sin(x/7) cos(y/11), joined by flat U-turn arcs of radius
// 0.25 mm that step 0.5 mm in Y; `blocks` motion blocks in total.
namespace kerf::motion::test {

struct RasterOptions {
    int blocks = 1000;
    double segMm = 0.2;
    double feedMmPerMin = 1500.0;
    bool leadIn = false;  // gen_nc's G0 Z5, G0 X0 Y0, G1 Z.. before the raster, M2 after
};

double rasterZ(double x, double y);
// Tool tip where the raster starts (on the surface at X0 Y0).
Pose rasterStart();
void emitRaster(const RasterOptions& options, canon::Sink& sink);

}  // namespace kerf::motion::test
