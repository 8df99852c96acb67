#include "core/interp/path/path_space.h"

#include <algorithm>
#include <cmath>

namespace kerf::interp {

namespace {

Pose between(const Pose& a, const Pose& b, double s) {
    Pose p;
    for (size_t i = 0; i < p.values.size(); ++i)
        p.values[i] = a.values[i] + s * (b.values[i] - a.values[i]);
    return p;
}

// A rotary axis turning this far within a piece is sampled again: a point turned about an axis
// lies off the chord of every arc shorter than a full turn, so with a sample at least every
// quarter turn whole turns cannot bring the tip back onto the straight move at the samples only
// (C+720 in one piece passes a test at its middle with X and Y standing still, while the tip on
// the part runs twice round and the axes, turning with it, would swing through their limits).
constexpr double kRotaryDegPerSample = 90.0;

int samplesOf(const Pose& start, const Pose& end) {
    double turn = 0.0;
    for (const Axis axis : {Axis::A, Axis::B, Axis::C})
        turn = std::max(turn, std::abs(end[axis] - start[axis]));
    return std::max(1, static_cast<int>(std::ceil(turn / kRotaryDegPerSample)));
}

// The largest distance between the element and where the straight move of the axes between a
// piece's ends passes it, at the middle of each piece (and, where the rotary axes turn far, at
// the middles of its quarter turns).
double worstDeviation(const PathSpace& space, const ContourElement& element, int pieces,
                      double toleranceMm) {
    double worst = 0.0;
    Pose start = space.toMachine(element.start);
    for (int i = 0; i < pieces && worst <= toleranceMm; ++i) {
        const Pose end = space.toMachine(space.along(element, double(i + 1) / pieces));
        const int samples = samplesOf(start, end);
        for (int j = 0; j < samples && worst <= toleranceMm; ++j) {
            const double s = (j + 0.5) / samples;
            const Pose passed = space.toPath(between(start, end, s));
            const Pose meant = space.along(element, (i + s) / pieces);
            worst = std::max(worst, space.deviation(passed, meant));
        }
        start = end;
    }
    return worst;
}

// How far the planner counts a straight move of the axes (motion/path: XYZ length, or the
// other axes' when X, Y, Z stand still), so that the feed given for it means what it should.
double plannedLength(const Pose& a, const Pose& b) {
    const double linear = (b.xyz() - a.xyz()).norm();
    if (linear >= 1e-9) return linear;
    double others = 0.0;
    for (size_t i = 3; i < a.values.size(); ++i)
        others += (b.values[i] - a.values[i]) * (b.values[i] - a.values[i]);
    return std::sqrt(others);
}

// The element's length in space: an arc's in its plane with the helix's rise.
double elementLength(const ContourElement& element) {
    const double chord = (element.end.xyz() - element.start.xyz()).norm();
    if (element.kind == ContourElement::Kind::Line) return chord;
    const Vec2 planar = element.end2() - element.start2();
    const double rise = std::sqrt(std::max(0.0, chord * chord - planar.squaredNorm()));
    return std::hypot(element.planarLength(), rise);
}

}  // namespace

bool machinePieces(const PathSpace& space, const ContourElement& element, double feed,
                   double toleranceMm, std::vector<MachinePiece>& out) {
    int pieces = 1;
    while (worstDeviation(space, element, pieces, toleranceMm) > toleranceMm) {
        if (pieces >= kMaxMachinePieces) return false;
        pieces *= 2;
    }
    Pose start = space.toMachine(element.start);
    for (int i = 0; i < pieces; ++i) {
        const Pose end = space.toMachine(space.along(element, double(i + 1) / pieces));
        // F TCP: the piece takes as long as the element's piece at F: a piece where only the
        // tables turn (the tip follows the element on the part while X, Y, Z stand) gets its
        // degrees' feed. F CONT: F is the axes' own feed.
        const double pathPiece = elementLength(element) / pieces;
        const double scaled = pathPiece > 1e-9 && space.feedAlongElement()
                                  ? feed * plannedLength(start, end) / pathPiece
                                  : feed;
        out.push_back({end, scaled > 0.0 ? scaled : feed});
        start = end;
    }
    return true;
}

}  // namespace kerf::interp
