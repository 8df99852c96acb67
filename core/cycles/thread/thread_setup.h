#pragma once

#include <optional>

#include "core/cycles/cycle_context.h"
#include "core/cycles/thread/thread_helix.h"

namespace kerf::cycles {

// Common set-up of the thread-milling cycles: checks the pitch and the tool against the nominal
// diameter Q335 and fills the helix (radius, direction, feeds) for a thread cut in `dw`.
std::optional<CycleError> threadHelix(int cycle, const CycleValues& values,
                                      const CycleContext& context, bool outside, double dw,
                                      const Feed& approach, ThreadHelix& helix);

// The working direction from the first non-zero of the given depths (spec: thread depth, then
// countersinking depth, then front depth); 0 when all are 0.
double firstNonZero(std::initializer_list<double> depths);

// Mills the thread passes of Q355 (0, 1 or k) between the surface and `depth`.
std::optional<CycleError> millThread(int cycle, CyclePath& path, const ThreadHelix& helix,
                                     const HoleLevels& levels, double depth, int perStep,
                                     bool towardsSurface);

}  // namespace kerf::cycles
