#pragma once

#include <array>
#include <cstdint>

#include "drivers/can/can_frame.h"

// Emergency messages of CiA 301 (COB-ID 0x080 + node, 8 bytes): error code (little-endian),
// error register (a copy of 0x1001), five bytes of manufacturer data. Code 0x0000 resets.
// Pure, any thread.
namespace kerf::drivers::canopen {

struct Emcy {
    uint16_t code = 0;
    uint8_t errorRegister = 0;
    std::array<uint8_t, 5> manufacturer{};
};

can::CanFrame emcyFrame(uint8_t node, const Emcy& emcy) noexcept;
// False unless `frame` is an 8-byte EMCY of node 1..127.
bool parseEmcy(const can::CanFrame& frame, uint8_t& node, Emcy& out) noexcept;

// Class of an error code by its high nibble/byte (CiA 301 table 21, CiA 402 for 0x8611 ...):
// "current", "voltage", "temperature", "device hardware", "device software", "additional
// modules", "monitoring", "communication", "external error", "additional functions", "device
// specific", "error reset", "generic error".
const char* emcyClassName(uint16_t code) noexcept;
// Text of a code CiA 301/402 name and drives report often ("following error", "heartbeat
// error", ...); the class name for any other code.
const char* emcyCodeText(uint16_t code) noexcept;

// Error register bits (0x1001) that go with a code's class: bit 0 generic always, plus current
// (bit 1), voltage (2), temperature (3), communication (4), device profile specific (5).
uint8_t errorRegisterFor(uint16_t code) noexcept;

}  // namespace kerf::drivers::canopen
