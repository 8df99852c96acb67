#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>

// One classical CAN frame (no CAN FD): identifier, flags and up to eight data bytes. A plain value
// used by every layer above drivers/can; any thread.
namespace kerf::drivers::can {

inline constexpr uint32_t kStandardIdMask = 0x7FF;
inline constexpr uint32_t kExtendedIdMask = 0x1FFFFFFF;
inline constexpr uint8_t kMaxDataLength = 8;

struct CanFrame {
    uint32_t id = 0;     // 11 bits, or 29 bits when `extended`
    uint8_t length = 0;  // data length code 0..8
    bool extended = false;
    bool remote = false;  // remote transmission request: no data bytes
    std::array<uint8_t, kMaxDataLength> data{};

    // Frames are equal when identifier, flags, length and the first `length` bytes are.
    friend constexpr bool operator==(const CanFrame& a, const CanFrame& b) noexcept {
        if (a.id != b.id || a.length != b.length || a.extended != b.extended ||
            a.remote != b.remote) {
            return false;
        }
        for (uint8_t i = 0; i < a.length && !a.remote; ++i) {
            if (a.data[i] != b.data[i]) return false;
        }
        return true;
    }
};

// A standard-identifier data frame with these bytes (at most eight are used).
constexpr CanFrame makeFrame(uint32_t id, std::initializer_list<uint8_t> bytes) noexcept {
    CanFrame frame;
    frame.id = id & kStandardIdMask;
    for (uint8_t b : bytes) {
        if (frame.length == kMaxDataLength) break;
        frame.data[frame.length++] = b;
    }
    return frame;
}

}  // namespace kerf::drivers::can
