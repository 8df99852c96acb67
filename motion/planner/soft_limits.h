#pragma once

#include <optional>

#include "motion/kinematics/machine_model.h"
#include "motion/path/path_geometry.h"

// Work-area check of a programmed move before it is accepted. Planner thread (pure).
namespace kerf::motion {

struct SoftLimitViolation {
    int axis = 0;              // kerf::Axis index
    double reached = 0.0;      // machine coordinate the move would reach
    double limit = 0.0;        // the soft limit it passes
    bool missingAxis = false;  // the move drives an axis the machine does not have
};

// Checks the whole element (arc and helix extremes included) in machine coordinates: tool tip
// plus work offset plus the tool length on the tool axis.
std::optional<SoftLimitViolation> checkSoftLimits(const MachineModel& model,
                                                  const PathGeometry& geometry, double toolLength);

}  // namespace kerf::motion
