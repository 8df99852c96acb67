#include "core/interp/path/path_space.h"

#include <algorithm>
#include <cmath>

namespace kerf::interp {

namespace {

Pose midway(const Pose& a, const Pose& b) {
    Pose p;
    for (size_t i = 0; i < p.values.size(); ++i)
        p.values[i] = 0.5 * (a.values[i] + b.values[i]);
    return p;
}

// The largest distance between the element's middle of a piece and where the straight move of
// the axes between the piece's ends passes it.
double worstDeviation(const PathSpace& space, const ContourElement& element, int pieces,
                      double toleranceMm) {
    double worst = 0.0;
    Pose start = space.toMachine(element.start);
    for (int i = 0; i < pieces && worst <= toleranceMm; ++i) {
        const Pose end = space.toMachine(space.along(element, double(i + 1) / pieces));
        const Pose passed = space.toPath(midway(start, end));
        const Pose meant = space.along(element, (i + 0.5) / pieces);
        worst = std::max(worst, space.deviation(passed, meant));
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
