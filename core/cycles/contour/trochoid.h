#pragma once

#include "core/cycles/contour/contour_train.h"

// Trochoidal milling along a slot's centre line (cycle 275): full circles about centres that
// advance along the line by a pitch, joined beside the line.
namespace kerf::cycles::contour {

double chainLength(const Chain& chain);

// Where the chain is `s` along it (clamped to its ends): the point, the direction of travel and
// the segment holding it.
struct ChainPoint {
    Vec2 point;
    Vec2 tangent;
    size_t segment = 0;
};
ChainPoint chainPointAt(const Chain& chain, double s);

// The loop centres: every `pitch` along the chain from its start, the last at its end.
std::vector<double> loopStations(double length, double pitch);

struct Trochoid {
    double loopRadius = 0.0;  // circles of this radius about the centres; 0: along the line
    double pitch = 0.0;
    bool counterClockwise = true;
    double edgeOffset = 0.0;  // != 0: the feed refers to the cutting edge on the loops (Q439)
};

// Mills from the chain's start (the tool there) to its end at the current height: to the first
// loop's side point, each loop a full circle, links beside the line (on an arc of the line an
// arc about the same centre), back onto the line at its end.
void runTrochoid(CyclePath& path, const Chain& chain, const Trochoid& t, const Feed& feed);

}  // namespace kerf::cycles::contour
