#pragma once

#include <cstdint>

// Operator commands to the servo cycle (task thread -> RT thread through an SPSC ring).
namespace kerf::motion {

enum class OperatorCommandKind : uint8_t {
    CycleStart,             // start or resume: program run, after a stop, hold or single block
    FeedHold,               // decelerate along the path and wait (resume with CycleStart)
    QuickStop,              // controlled stop along the path, then abort the program
    EmergencyStop,          // drives quick-stop and disable at once; the program is aborted
    Reset,                  // leave the emergency stop / fault state and enable the drives
    FeedOverride,           // value = 0 .. 1.5
    RapidOverride,          // value = 0 .. 1
    SpindleOverride,        // value = 0.5 .. 1.2
    SingleBlock,            // flag
    SingleBlockEveryBlock,  // flag: single block stops after a block without a move too (FAGOR)
    OptionalStop,           // flag: M1 stops
    JogContinuous,          // joint, value = signed velocity (units/s); JogStop ends it
    JogStop,                // joint
    JogIncrement,           // joint, value = signed distance, value2 = velocity
    Handwheel,              // joint, value = signed distance of the counts since the last command
    Home,                   // joint = -1: all joints in order; else one joint
    // Manual operation without a program: at once, also while the spindle still ramps.
    ManualSpindle,  // joint = direction (0 stop, 1 cw, -1 ccw), value = rpm
    ManualCoolant,  // joint = bit 0 flood, bit 1 mist
};

struct OperatorCommand {
    OperatorCommandKind kind = OperatorCommandKind::CycleStart;
    int32_t joint = -1;
    double value = 0.0;
    double value2 = 0.0;
    bool flag = false;
};

}  // namespace kerf::motion
