#include "motion/port/drive_bus.h"

#include "motion/port/motion_status.h"

namespace kerf::motion {

const char* driveStateName(DriveState state) noexcept {
    switch (state) {
        case DriveState::Disabled:
            return "disabled";
        case DriveState::Enabling:
            return "enabling";
        case DriveState::Enabled:
            return "enabled";
        case DriveState::QuickStop:
            return "quick stop";
        case DriveState::Fault:
            return "fault";
    }
    return "?";
}

const char* motionModeName(MotionMode mode) noexcept {
    switch (mode) {
        case MotionMode::Idle:
            return "idle";
        case MotionMode::Program:
            return "program";
        case MotionMode::Hold:
            return "hold";
        case MotionMode::Stopped:
            return "stopped";
        case MotionMode::Jog:
            return "jog";
        case MotionMode::Returning:
            return "returning";
        case MotionMode::Homing:
            return "homing";
        case MotionMode::Stopping:
            return "stopping";
        case MotionMode::EmergencyStop:
            return "emergency stop";
        case MotionMode::Fault:
            return "fault";
    }
    return "?";
}

}  // namespace kerf::motion
