#pragma once

#include <array>

#include "core/machine/machine_config.h"
#include "motion/path/path_geometry.h"
#include "motion/port/motion_status.h"

// The machine as motion sees it: per-axis limits indexed by kerf::Axis, the joints (one per
// enabled axis, plus the spindle), the servo period and the smoothing filter. Built once from a
// MachineConfig in a normal thread; read-only afterwards (any thread, including RT).
namespace kerf::motion {

struct MotionOptions {
    AxisVector workOffset{};  // machine = workpiece + offset (+ tool length on the tool axis)
    double spindleAccelRevPerS2 = 50.0;  // 3000 rpm/s
    double spindleJerkRevPerS3 = 1000.0;
    double filterTimeS = 0.0;  // axis smoothing filter; 0: derived from tolerance and jerk
    double maxFeedOverride = 1.5;
    bool startHomed = true;            // simulation: joints count as homed at start
    double jogVelocityFraction = 0.2;  // continuous jog default, of the axis velocity
    // Runs of short lines followed as a curve fitted within the tolerance (docs/motion.md);
    // off: every vertex is a corner (for tests of the look-ahead on many short elements).
    bool smoothPolylines = true;
};

struct AxisModel {
    bool enabled = false;
    bool rotary = false;
    double minLimit = 0.0;  // machine coordinates
    double maxLimit = 0.0;
    double velocity = 0.0;  // per s
    double accel = 0.0;     // per s^2
    double jerk = 0.0;      // per s^3
    double home = 0.0;
    int homeSequence = 1;  // Home all: lower numbers first
};

struct MachineModel {
    std::array<AxisModel, kAxisCount> axes{};
    int jointCount = 0;                       // axes + spindle
    std::array<int, kMaxJoints> jointAxis{};  // axis index per joint; -1: the spindle
    int spindleJoint = -1;
    // Home all: the axis joints in the machine file's reference order (home_sequence, then
    // display order).
    std::array<int, kMaxJoints> homingOrder{};
    int homingCount = 0;
    int toolAxis = 2;
    double periodS = 0.001;
    int filterTaps = 1;  // moving-average length in servo cycles
    double rapidVelocity = 0.0;
    double maxFeed = 0.0;
    double toleranceMm = 0.01;
    double spindleMaxRpm = 0.0;
    MotionOptions options;

    double filterTimeS() const { return periodS * filterTaps; }
};

MachineModel makeMachineModel(const machine::MachineConfig& config, const MotionOptions& options);

// Joint position of a tool-tip position (workpiece coordinates) with a tool length on the tool
// axis, and back. O(joints), noexcept: RT-safe.
double jointFromAxis(const MachineModel& model, int axis, double tip, double toolLength) noexcept;
double axisFromJoint(const MachineModel& model, int axis, double joint, double toolLength) noexcept;

}  // namespace kerf::motion
