#pragma once

#include <cstdint>

#include "core/base/source_location.h"
#include "motion/path/path_geometry.h"

// What the servo cycle publishes: a status snapshot (seqlock) and events (SPSC ring), both
// written by the RT thread and read by normal threads.
namespace kerf::motion {

inline constexpr int kMaxJoints = 10;  // nine axes and the spindle

enum class MotionMode : uint8_t {
    Idle,       // nothing queued
    Program,    // running queued items
    Hold,       // feed hold: stopping or stopped on the path
    Stopped,    // program stop, single block or sync point: waiting for cycle start / the task
    Jog,        // manual motion (jog, increment, handwheel), also away from an interrupted program
    Returning,  // back to the point where the program was interrupted, then Program
    Homing,
    Stopping,  // quick stop in progress
    EmergencyStop,
    Fault,
};

const char* motionModeName(MotionMode mode) noexcept;

struct MotionStatus {
    MotionMode mode = MotionMode::Idle;
    uint64_t cycle = 0;
    double timeS = 0.0;
    AxisVector commandedPosition{};  // tool tip, workpiece coordinates (the setpoints)
    AxisVector actualPosition{};     // tool tip from the drive feedback
    double pathPosition = 0.0;       // interpolator position along the path (mm since start)
    double pathVelocity = 0.0;       // interpolator velocity along the path
    double feedOverride = 1.0;
    double rapidOverride = 1.0;
    double spindleOverride = 1.0;
    double spindleRpm = 0.0;
    double spindleAngleDeg = 0.0;
    uint64_t itemSequence = 0;  // item being executed
    SourceLocation source;      // its block
    uint32_t queued = 0;        // items waiting in the ring
    uint16_t homedMask = 0;     // bit per joint
    uint8_t coolant = 0;        // bit 0 flood, bit 1 mist (as the Coolant action)
    bool singleBlock = false;
    bool emergencyStopOpen = false;  // the E-stop chain is open: the machine cannot be switched on
    uint64_t lateCycles = 0;         // cycles that started later than one period after the previous
    double maxCycleCpuS = 0.0;       // longest servo cycle computation
    double maxFollowingError = 0.0;
};

enum class MotionEventKind : uint8_t {
    ItemRejected,    // value = reason (MotionError)
    SyncReached,     // the machine stands at a sync point: position = actual position
    ProbeTriggered,  // position = latched tool tip
    ProbeMissed,     // the probe move ended without a trigger
    ProgramStopped,  // M0/M1/single block: waiting for cycle start
    ProgramEnd,
    Fault,       // joint, value = fault code
    Error,       // value = MotionError
    HomingDone,  // joint
    Aborted,     // quick stop or emergency stop ended the program
};

enum class MotionError : uint8_t {
    None,
    SoftLimit,  // a jog or handwheel target beyond a soft limit was clipped
    DriveFault,
    BusError,
    FollowingError,
    QueueStarved,  // the program ran out of planned segments and stopped on the path
    NotHomed,
};

struct MotionEvent {
    MotionEventKind kind = MotionEventKind::Error;
    uint64_t sequence = 0;
    int32_t joint = -1;
    double value = 0.0;
    double timeS = 0.0;
    AxisVector position{};
    SourceLocation source;
};

}  // namespace kerf::motion
