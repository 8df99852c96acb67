#include "drivers/can/bit_timing.h"

#include <array>

namespace kerf::drivers::can {

namespace {

// The stuffed part of a frame: start of frame, arbitration and control fields, data, CRC.
class BitStream {
public:
    void append(uint32_t value, int bits) noexcept {
        for (int i = bits - 1; i >= 0; --i)
            m_bits[m_count++] = static_cast<uint8_t>((value >> i) & 1u);
    }
    void appendCrc() noexcept {
        // CRC-15 of ISO 11898-1: generator x^15+x^14+x^10+x^8+x^7+x^4+x^3+1 (0x4599).
        uint32_t crc = 0;
        for (size_t i = 0; i < m_count; ++i) {
            uint32_t next = m_bits[i] ^ ((crc >> 14) & 1u);
            crc = (crc << 1) & 0x7FFF;
            if (next) crc ^= 0x4599;
        }
        append(crc, 15);
    }
    uint32_t stuffBits() const noexcept {
        uint32_t stuffed = 0;
        int run = 0;
        uint8_t last = 2;
        for (size_t i = 0; i < m_count; ++i) {
            uint8_t bit = m_bits[i];
            run = bit == last ? run + 1 : 1;
            last = bit;
            if (run == 5) {
                // The stuff bit is the opposite value and starts the next run.
                ++stuffed;
                last = static_cast<uint8_t>(!bit);
                run = 1;
            }
        }
        return stuffed;
    }

private:
    std::array<uint8_t, 160> m_bits{};
    size_t m_count = 0;
};

}  // namespace

uint32_t frameBitCount(const CanFrame& frame) noexcept {
    uint8_t length = frame.length > kMaxDataLength ? kMaxDataLength : frame.length;
    uint8_t payload = frame.remote ? 0 : length;
    BitStream s;
    s.append(0, 1);  // start of frame
    if (frame.extended) {
        s.append((frame.id >> 18) & 0x7FF, 11);
        s.append(1, 1);  // SRR
        s.append(1, 1);  // IDE
        s.append(frame.id & 0x3FFFF, 18);
        s.append(frame.remote ? 1 : 0, 1);
        s.append(0, 2);  // r1, r0
    } else {
        s.append(frame.id & kStandardIdMask, 11);
        s.append(frame.remote ? 1 : 0, 1);
        s.append(0, 2);  // IDE, r0
    }
    s.append(length, 4);
    for (uint8_t i = 0; i < payload; ++i)
        s.append(frame.data[i], 8);
    s.appendCrc();
    // CRC delimiter, ACK slot, ACK delimiter, end of frame (7) and intermission (3) are not
    // stuffed.
    return unstuffedBitCount(payload, frame.extended) + s.stuffBits();
}

std::chrono::nanoseconds frameDuration(const CanFrame& frame, uint32_t bitrate) noexcept {
    if (bitrate == 0) return std::chrono::nanoseconds(0);
    uint64_t bits = frameBitCount(frame);
    return std::chrono::nanoseconds(static_cast<int64_t>(bits * 1'000'000'000ull / bitrate));
}

}  // namespace kerf::drivers::can
