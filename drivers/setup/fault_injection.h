#pragma once

#include <cstdint>
#include <string_view>

#include "core/base/expected.h"

// A fault the simulated drive set injects at a simulated time: the runner's
// --inject-fault NODE:KIND@SECONDS. Node 0 means the master's own CAN controller (bus-off,
// error-passive only). Faults of the boot (slow-boot, identity, sdo-abort) act from power-on.
namespace kerf::drivers {

enum class FaultKind : uint8_t {
    Heartbeat,       // the drive stops its heartbeat
    Emcy,            // the drive faults with EMCY 0x4310 (excess temperature)
    FollowingError,  // an overload pushes the axis away until the drive trips (0x8611)
    Encoder,         // the encoder fails (0x7305); a fault reset cannot clear it
    Pdo,             // the drive stops sending its TPDO
    Silent,          // the drive falls silent and its power stage goes off
    SlowBoot,        // boot-up comes after the master's 5 s boot-up timeout
    Identity,        // the drive reports another product code (0x1018 sub 2)
    SdoAbort,        // the drive aborts the write of its heartbeat time (0x1017)
    BusOff,          // the node's (node 0: the master's) CAN controller goes bus off
    ErrorPassive,    // the node's (node 0: the master's) CAN controller goes error passive
};

struct FaultInjection {
    uint8_t node = 0;
    FaultKind kind = FaultKind::Heartbeat;
    double timeS = 0.0;  // simulated time since power-on, as in the CAN trace
};

const char* faultKindName(FaultKind kind) noexcept;
// Parses "2:heartbeat@1.5"; the message lists the kinds on a bad kind.
Expected<FaultInjection> parseFaultInjection(std::string_view text);

}  // namespace kerf::drivers
