#pragma once

#include "core/interp/fagor/iso_block.h"
#include "core/interp/fagor/problem.h"

namespace kerf::fagor {

// The rules on a block's G functions that do not depend on the modal state (spec part 1 §3.5,
// §5.1): the number exists, no two functions of one group, functions that must be alone in their
// block. Canned cycles, probing and G46 are "not supported" problems of their own code
// ("not-supported"), which the program check reports as warnings.
bool checkGFunctions(const IsoBlock& iso, Problem& problem);

}  // namespace kerf::fagor
