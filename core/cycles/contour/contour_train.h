#pragma once

#include <optional>
#include <vector>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_path.h"

// What cycle 25 CONTOUR TRAIN (and later 276) needs: the tool-centre path beside a programmed
// path, its direction for climb or up-cut, and cycle 270's approach and departure.
namespace kerf::cycles::contour {

using Chain = std::vector<PlanarSegment>;

Chain reversedChain(const Chain& chain);

// The side of the tool (+1 left, -1 right, 0 on the path): the subprogram's RL/RR, or cycle
// 270's Q391 (then the subprogram must be written without compensation).
std::optional<CycleError> trainToolSide(int cycle, const CycleContext& context, int& side);

// The tool centre `distance` (>= 0) beside the path on side `side` (+1 left of its direction,
// -1 right, 0 on the path itself). A closed path gives a closed path starting nearest to its
// start. Empty when the tool does not fit (the offset vanishes or splits).
Chain trainCentrePath(const ContourTrain& train, int side, double distance);

// Cycle 270: how the tool reaches the path and leaves it, from the free side.
struct TrainApproach {
    enum class Kind : uint8_t { Straight = 0, Arc = 1, Tangent = 2, Perpendicular = 3 };
    Kind kind = Kind::Straight;  // Straight: down onto the path without an approach move
    double radius = 0.0;         // Q392
    double angleRad = 0.0;       // Q393
    double distance = 0.0;       // Q394
};
TrainApproach readTrainApproach(const CycleValues* data);

// Where the approach starts for a path whose free side is `freeSide` (+1 left of the travel, -1
// right); the approach and departure moves at `feed` (the path's start and end).
Vec2 approachStart(const TrainApproach& a, const Chain& path, int freeSide);
void approachPath(CyclePath& path, const TrainApproach& a, const Chain& chain, int freeSide,
                  const Feed& feed);
void departPath(CyclePath& path, const TrainApproach& a, const Chain& chain, int freeSide,
                const Feed& feed);

// Follows an open or closed chain from its start at the current tool-axis height.
void followChain(CyclePath& path, const Chain& chain, const Feed& feed);

// Cycle 276: the tool-axis coordinate of the programmed path where it is nearest to `p` (ties:
// the first segment, or the last with `fromEnd`), each segment's height linear along it.
double heightNear(const ContourTrain& train, const Vec2& p, bool fromEnd);

// Follows a chain beside a 3-D path: each segment ends at the path's height there plus `shift`.
void followChain3d(CyclePath& path, const Chain& chain, const ContourTrain& train, double shift,
                   const Feed& feed);

}  // namespace kerf::cycles::contour
