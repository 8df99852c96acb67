#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "drivers/can/can_frame.h"

// The cannelloni v2 UDP data format, so that a cannelloni bridge on a host with kernel CAN can
// join a UDP bus: a 5-byte header {version 2, op code 0 = DATA, sequence number, frame count
// (big-endian u16)} and per frame {can_id as in <linux/can.h> (big-endian u32, EFF/RTR flags in
// the top bits), length, data bytes (none for a remote request)}. Pure functions, any thread.
namespace kerf::drivers::can {

inline constexpr size_t kCannelloniHeaderSize = 5;
inline constexpr size_t kCannelloniMaxFrameSize = 4 + 1 + kMaxDataLength;

// Writes a datagram holding one frame into `out` (at least 18 bytes); returns its size.
size_t encodeCannelloni(const CanFrame& frame, uint8_t sequence, std::span<uint8_t> out) noexcept;

// Decodes up to out.size() frames of a datagram; returns how many, or -1 when it is malformed
// (wrong version or op code, truncated, CAN FD frames).
int decodeCannelloni(std::span<const uint8_t> datagram, std::span<CanFrame> out) noexcept;

}  // namespace kerf::drivers::can
