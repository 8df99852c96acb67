#pragma once

#include <chrono>
#include <cstdint>

#include "drivers/can/can_frame.h"

// How long a frame occupies the bus (ISO 11898-1 classical frames). A frame with n data bytes and
// an 11-bit identifier has 47 + 8n bits including the 3-bit intermission, plus stuff bits: after
// five equal bits the sender inserts one opposite bit, from the start of frame to the end of the
// CRC (34 + 8n bits), which adds at most floor((33 + 8n) / 4). Pure functions, any thread.
namespace kerf::drivers::can {

// Bits on the wire without stuff bits.
constexpr uint32_t unstuffedBitCount(uint8_t length, bool extended = false) noexcept {
    return (extended ? 67u : 47u) + 8u * length;
}

// Upper bound with the most stuff bits any payload can cause.
constexpr uint32_t worstCaseBitCount(uint8_t length, bool extended = false) noexcept {
    uint32_t stuffable = (extended ? 54u : 34u) + 8u * length;
    return unstuffedBitCount(length, extended) + (stuffable - 1u) / 4u;
}

// Exact count for this frame: builds the bit stream with its CRC-15 and counts the stuff bits.
uint32_t frameBitCount(const CanFrame& frame) noexcept;

// Time on the wire at `bitrate` bit/s; zero when bitrate is zero (a bus without timing).
std::chrono::nanoseconds frameDuration(const CanFrame& frame, uint32_t bitrate) noexcept;

}  // namespace kerf::drivers::can
