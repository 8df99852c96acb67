#include "core/interp/path/path_space.h"

#include <algorithm>

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
        const Pose end = space.toMachine(element.poseAt(double(i + 1) / pieces));
        const Vec3 passed = space.toPath(midway(start, end)).xyz();
        const Vec3 meant = element.poseAt((i + 0.5) / pieces).xyz();
        worst = std::max(worst, (passed - meant).norm());
        start = end;
    }
    return worst;
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
    Pose from = element.start;
    for (int i = 0; i < pieces; ++i) {
        const Pose to = element.poseAt(double(i + 1) / pieces);
        const Pose end = space.toMachine(to);
        const double pathPiece = (to.xyz() - from.xyz()).norm();
        const double axesPiece = (end.xyz() - start.xyz()).norm();
        out.push_back({end, pathPiece > 1e-9 ? feed * axesPiece / pathPiece : feed});
        start = end;
        from = to;
    }
    return true;
}

}  // namespace kerf::interp
