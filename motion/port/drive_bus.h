#pragma once

#include <cstdint>
#include <span>

// The servo cycle's view of the drives: one joint per drive axis (a CiA 402 drive in cyclic
// synchronous position mode, or a simulated one). Every function is called from the RT thread
// only, is O(1) per joint, noexcept and allocation-free.
namespace kerf::motion {

enum class DriveState : uint8_t {
    Disabled,   // CiA 402: switch on disabled / ready to switch on / switched on
    Enabling,   // transition requested, not yet operation enabled
    Enabled,    // operation enabled: follows the position setpoint
    QuickStop,  // quick stop active: the drive brakes on its own ramp
    Fault,      // fault (code in faultCode); needs a fault reset
};

const char* driveStateName(DriveState state) noexcept;

struct JointFeedback {
    double position = 0.0;  // actual position, joint units (mm or deg), homing offset applied
    DriveState state = DriveState::Disabled;
    uint16_t faultCode = 0;     // CiA 402 error code (0x603F) when state == Fault
    bool homeSwitch = false;    // digital input of the reference switch
    bool probeLatched = false;  // touch probe latched a new position this cycle
    double probePosition = 0.0;
};

struct JointSetpoint {
    double position = 0.0;  // target position, joint units
};

enum class DriveRequest : uint8_t { Enable, Disable, QuickStop, FaultReset };

enum class BusResult : uint8_t {
    Ok,
    Late,   // feedback of this cycle missing (bus overrun); the last values are repeated
    Error,  // bus down: treat as a fault of every joint
};

class DriveBus {
public:
    virtual ~DriveBus() = default;
    virtual int jointCount() const noexcept = 0;
    // Start of a cycle: feedback of every joint (feedback.size() == jointCount()).
    virtual BusResult read(std::span<JointFeedback> feedback) noexcept = 0;
    // End of a cycle: setpoints of every joint.
    virtual BusResult write(std::span<const JointSetpoint> setpoints) noexcept = 0;
    // State change of every joint, applied by the next cycles (CiA 402 controlword).
    virtual void request(DriveRequest request) noexcept = 0;
    // Homing: the current actual position of `joint` becomes `position` (applied at once).
    virtual void setPosition(int joint, double position) noexcept = 0;
    // Touch probe: arm (or disarm) the latch of every joint on the probe input edge.
    virtual void armProbe(bool armed) noexcept = 0;
    // The emergency-stop chain (the mushroom button's contacts): true while it is open. Read
    // every cycle; a bus without such an input reports it closed.
    virtual bool emergencyStopOpen() const noexcept { return false; }
};

}  // namespace kerf::motion
