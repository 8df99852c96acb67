#pragma once

#include <system_error>

// Why the master refused or lost a node, apart from SDO aborts (category "canopen.master").
namespace kerf::drivers::canopen {

enum class MasterErrc {
    BootUpTimeout = 1,   // no boot-up message after the reset-communication command
    DeviceTypeMismatch,  // 0x1000 is not the configured profile / device kind
    IdentityMismatch,    // 0x1018 vendor or product differs from the configuration
    ModeNotSupported,    // 0x6502 lacks a mode the axis needs
    ReadBackMismatch,    // a value read back (0x6061) differs from the one written
    NotOperational,      // no heartbeat reporting Operational after the start command
    HeartbeatLost,       // consumer heartbeat time expired
    UnexpectedNmtState,  // an operational node reported boot-up, stopped or pre-operational
    PdoMissing,          // the TPDO did not arrive for the configured number of SYNC cycles
};

const std::error_category& masterCategory() noexcept;
std::error_code make_error_code(MasterErrc e) noexcept;

}  // namespace kerf::drivers::canopen

template <>
struct std::is_error_code_enum<kerf::drivers::canopen::MasterErrc> : std::true_type {};
