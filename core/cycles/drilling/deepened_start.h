#pragma once

#include <algorithm>

#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {

// Positions of the Q379 rule of cycles 205 and 241 (spec §2, "Positioning with Q379"): with a
// deepened starting point P = Q379 below the surface, drilling starts min(0.2·Q379, Q200) above P
// and chips are removed min(0.8·Q379, Q200) above P; without it both are the set-up clearance.
struct DeepenedStart {
    double drillStart = 0.0;
    double retract = 0.0;
};

inline DeepenedStart deepenedStart(const HoleLevels& levels, double q379, double q200) {
    if (q379 <= 0.0) return {levels.clearance, levels.clearance};
    const double p = levels.at(q379);
    return {p + levels.up * std::min(0.2 * q379, q200), p + levels.up * std::min(0.8 * q379, q200)};
}

}  // namespace kerf::cycles
