#pragma once

#include <optional>
#include <vector>

#include "core/cycles/contour/contour_train.h"

// Rest machining of cycles 25 and 276 (Q18, Q446-Q448): the parts of the fine tool's centre path
// where a coarser tool, run along the same contour before, left material.
namespace kerf::cycles::contour {

struct TrainRest {
    double residual = 0.01;   // Q446: thinner rest is left
    double connection = 0.0;  // Q447: rest pieces closer than this along the path are joined
    double extension = 0.0;   // Q448: each piece lengthened at both ends along the path
};

// The pieces of `fine` (the fine tool's centre path, radius `fineRadius`) where its tool sticks
// out of what the coarse tool (centre path `coarse`, radius `coarseRadius`) swept by more than
// Q446: a point P of `fine` is such when its distance from `coarse` exceeds coarseRadius -
// fineRadius + Q446. Each piece is lengthened by Q448 (within an open path), pieces whose gap
// along the path is at most Q447 are one. On a closed path (its end on its start) a piece may run
// across the start: the rest around it is one piece, ordered last. An empty `coarse` (the coarse
// tool did not fit) leaves the whole path.
std::vector<Chain> restPieces(const Chain& fine, double fineRadius, const Chain& coarse,
                              double coarseRadius, const TrainRest& rest);

// The coarse roughing tool Q18 of `cycle` from the tool table, or an error.
std::optional<CycleError> coarseTool(int cycle, const CycleValues& values,
                                     const CycleContext& context, ToolInfo& out);

}  // namespace kerf::cycles::contour
