#pragma once

#include <vector>

#include "core/cycles/cycle_path.h"
#include "core/cycles/drilling/hole_levels.h"

// Helical paths of the thread-milling cycles 262-267 (spec §3, thread-milling fundamentals).
namespace kerf::cycles {

struct ThreadHelix {
    Vec2 centre{0.0, 0.0};
    double radius = 0.0;   // tool-centre path radius: nominal radius -/+ tool radius
    double pitch = 0.0;    // > 0
    double dw = 1.0;       // +1: the tool-axis coordinate grows while cutting
    bool ccw = true;       // DR+
    bool outside = false;  // 267: approach from outside the stud
    Feed prePosition;      // Q253
    Feed approach;         // Q512 (or Q207)
    Feed mill;             // Q207 scaled to the tool centre
};

// The tool-axis direction of cutting: towards the surface for right-hand climb milling inside
// (table in spec §3), and the opposite for an outside thread.
bool cutsTowardsSurface(double pitch, int climbOrUpCut, bool outside);
// DR+ when a right-hand thread advances along +w (and a left-hand one against it).
bool threadCcw(double pitch, double dw);

// One helical pass: compensating move to half a pitch before `wStart`, tangential helical
// approach (half turn) to the diameter at `wStart`, `turns` revolutions, tangential helical
// departure (half turn) back to the centre (inside) or outwards (outside, then around the stud
// back to the start point).
void millThreadPass(CyclePath& path, const ThreadHelix& helix, double wStart, double turns);

struct ThreadPass {
    double depthStart = 0.0;  // depth below the surface where the pass starts
    double turns = 0.0;
};
// Passes for Q355: 0 one 360° helix at the bottom, 1 one continuous helix over the depth, k > 1
// passes of k turns. Capped; empty when there are too many.
std::vector<ThreadPass> threadPasses(double depth, double pitch, int perStep, bool towardsSurface);

// Centre-path feed for a feed programmed at the cutting edge.
Feed centreFeed(const Feed& edgeFeed, double nominalRadius, double pathRadius);

// Front-face countersinking: half circle out from the centre to `radius`, a full circle, half
// circle back to the centre, all at `feed`.
void frontCircle(CyclePath& path, const Vec2& centre, double radius, bool ccw, const Feed& feed);

}  // namespace kerf::cycles
