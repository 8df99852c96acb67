#pragma once

#include <array>
#include <cstdint>

#include "core/base/source_location.h"
#include "core/geometry/axes.h"

// What the operator's displays show about the machine: a plain value the task thread copies from
// motion (MotionPort::status()) and hands to the HMI. No behaviour, any thread.
namespace kerf::task {

enum class MachineState : uint8_t {
    Idle,
    Running,  // a program or MDI block moves the axes
    Held,     // feed hold
    Stopped,  // program stop, single block: waiting for cycle start
    Jogging,  // manual motion
    Homing,
    Stopping,  // quick stop in progress
    EmergencyStop,
    Fault,
    Offline,  // no machine (programming station, test run)
};

const char* machineStateName(MachineState state);

struct AxisStatus {
    bool enabled = false;
    bool homed = false;
    // Workpiece coordinates of the tool tip: commanded (nominal) and from the drive feedback.
    double nominal = 0.0;
    double actual = 0.0;
    // Machine coordinates (reference system) of the same points.
    double machineNominal = 0.0;
    double machineActual = 0.0;
    double followingError = 0.0;  // nominal - actual
    double distanceToGo = 0.0;    // to the end of the move being executed
};

struct MachineStatus {
    MachineState state = MachineState::Offline;
    std::array<AxisStatus, kAxisCount> axes{};
    double programmedFeedMmPerMin = 0.0;
    double actualFeedMmPerMin = 0.0;  // along the path
    double programmedSpindleRpm = 0.0;
    double programmedSurfaceSpeedMPerMin = 0.0;  // constant surface speed (G96), 0 without
    double actualSpindleRpm = 0.0;
    double feedOverride = 1.0;  // fractions: 1 = 100 %
    double rapidOverride = 1.0;
    double spindleOverride = 1.0;
    int toolNumber = 0;    // 0: no tool
    bool coolant = false;  // flood or mist on
    bool singleBlock = false;
    bool emergencyStopOpen = false;  // the E-stop chain is open (button pressed)
    double servoTimeS = 0.0;  // the servo cycle's clock (simulated time on a simulated machine)
    SourceLocation block;     // the block being executed
};

}  // namespace kerf::task
