#pragma once

#include <vector>

#include "core/canon/commands.h"

namespace kerf::graphics {

// Splits a circular or helical move into chords. The points returned run from the first point
// after `start` to the arc's end point (its programmed target), none of them `start` itself; the
// chords deviate from the true arc by at most `chordToleranceMm` unless `maxPoints` caps them.
// A degenerate arc (zero radius, zero sweep, not finite) gives the target alone, so callers draw
// a straight line to it and never divide by zero.
void tessellateArc(const Pose& start, const canon::ArcMove& arc, double chordToleranceMm,
                   int maxPoints, std::vector<Vec3>& out);

// Number of chords tessellateArc uses for a radius and sweep (at least 1).
int arcChordCount(double radiusMm, double sweepRad, double chordToleranceMm, int maxPoints);

// True when every coordinate of the three linear axes is a finite number.
bool finiteXyz(const Pose& pose);

}  // namespace kerf::graphics
