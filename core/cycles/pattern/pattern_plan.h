#pragma once

#include <optional>
#include <vector>

#include "core/geometry/axes.h"

namespace kerf::cycles {

// A machining position of a pattern (PATTERN DEF, point table, cycle 220/221) in the working
// plane, with the workpiece surface it brings along, if any.
struct PatternPoint {
    Vec2 position{0.0, 0.0};
    std::optional<double> surface;  // replaces the cycle's Q203 (PATTERN DEF Z != 0)
    double surfaceOffset = 0.0;     // added to the cycle's Q203 (point table Z)
};

// How a pattern cycle (220, 221) moves between its points.
struct PatternPlan {
    std::vector<PatternPoint> points;
    double setUpClearance = 0.0;           // Q200
    double surface = 0.0;                  // Q203
    double secondClearance = 0.0;          // Q204
    bool travelAtSecondClearance = false;  // Q301
    bool arcTraverse = false;              // Q365 = 1: on the pitch circle
    Vec2 arcCentre{0.0, 0.0};
    double arcStepRad = 0.0;            // sweep from one point to the next
    std::optional<double> rotationDeg;  // 221: Q224 handed to the machining cycle
};

}  // namespace kerf::cycles
