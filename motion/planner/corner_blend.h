#pragma once

#include <array>

#include "motion/path/path_geometry.h"

// Corner blending: replaces the corner between two XYZ path elements by one circular arc (line
// to line) or a biarc (two arcs, when an arc is involved), tangent to both elements, so that the
// blend stays within `deviation` of the programmed path. Planner thread.
namespace kerf::motion {

struct CornerBlend {
    double trimBefore = 0.0;  // length removed from the end of the first element
    double trimAfter = 0.0;   // length removed from the start of the second element
    std::array<PathGeometry, 2> arcs{};
    int arcCount = 0;
    double deviation = 0.0;  // largest distance of the blend from the programmed path
};

// Angle between the end tangent of `before` and the start tangent of `after` (radians).
double cornerAngle(const PathGeometry& before, const PathGeometry& after);

// `maxTrimBefore` / `maxTrimAfter` bound how much of each element the blend may use.
// Empty (arcCount == 0) when the corner is tangent.
CornerBlend blendCorner(const PathGeometry& before, const PathGeometry& after, double deviation,
                        double maxTrimBefore, double maxTrimAfter);

// The same corner with exactly `trimBefore` taken from the first element (a biarc, so that no
// sliver of it is left between two blends). Empty when that deviates too much.
CornerBlend blendCornerFrom(const PathGeometry& before, const PathGeometry& after, double deviation,
                            double trimBefore, double trimAfter);

// One blend across a short element `middle` between `before` and `after`, in place of the two
// corners at its ends (a kink of a short segment, where each corner could use only half of it):
// a biarc from `before` (as much of its end as fits, up to `maxTrimBefore`) to `trimAfter` into
// `after`, within `deviation` of all three. Empty when no trim fits.
CornerBlend blendAcross(const PathGeometry& before, const PathGeometry& middle,
                        const PathGeometry& after, double deviation, double maxTrimBefore,
                        double trimAfter);

}  // namespace kerf::motion
