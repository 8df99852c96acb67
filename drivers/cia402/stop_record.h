#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <system_error>

#include "drivers/canopen/nmt.h"
#include "drivers/canopen/sdo_protocol.h"
#include "drivers/cia402/state_machine.h"

// Why the drive set stopped (or warned): a fixed-size record the RT cycle fills, formatted into
// text by a normal thread.
namespace kerf::drivers::cia402 {

enum class StopReason : uint8_t {
    DriveFault,  // statusword Fault / Fault reaction active
    Emergency,   // an EMCY from a started node
    HeartbeatLost,
    PdoMissing,
    UnexpectedNmtState,  // the node reported boot-up, stopped or pre-operational
    BootFailed,
    EnableTimeout,    // a transition was not confirmed within the step timeout
    UnexpectedState,  // the drive left Operation enabled on its own
    TargetIgnored,    // CSP/CSV statusword bit 12 dropped
    FollowingError,   // statusword bit 13, or the master's own check
    SetpointJump,     // the first setpoint after enabling was far from the actual position
    BusOff,           // the master's CAN controller
    // Warnings (no stop):
    ErrorPassive,
    EmergencyWarning,  // an EMCY whitelisted as a warning, or from a node not yet started
};

struct StopRecord {
    StopReason reason = StopReason::DriveFault;
    int joint = -1;  // -1: the whole bus
    uint8_t node = 0;
    uint16_t code = 0;  // CiA 301/402 error code: EMCY code, or the one that fits the reason
    uint8_t errorRegister = 0;
    State state = State::NotReadyToSwitchOn;  // the drive's state when it happened
    std::chrono::nanoseconds time{0};
    std::error_code error;          // boot failures, losses
    canopen::ObjectAddress object;  // boot failures: the object
    double value = 0.0;             // following error, setpoint jump (joint units)
    canopen::NmtState nmtState = canopen::NmtState::Operational;  // UnexpectedNmtState
};

// "heartbeat lost (consumer time 250 ms)", "EMCY 0x8611 following error, error register 0x21",
// ... One line, English, without node and time (the caller adds them).
std::string describeStop(const StopRecord& record);

}  // namespace kerf::drivers::cia402
