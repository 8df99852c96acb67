#include "drivers/can/cannelloni_codec.h"

namespace kerf::drivers::can {

namespace {

constexpr uint8_t kVersion = 2;
constexpr uint8_t kOpData = 0;
constexpr uint32_t kEffFlag = 0x80000000u;  // CAN_EFF_FLAG
constexpr uint32_t kRtrFlag = 0x40000000u;  // CAN_RTR_FLAG
constexpr uint32_t kErrFlag = 0x20000000u;  // CAN_ERR_FLAG
constexpr uint8_t kCanFdFlag = 0x80;        // cannelloni marks CAN FD frames in the length

}  // namespace

size_t encodeCannelloni(const CanFrame& frame, uint8_t sequence, std::span<uint8_t> out) noexcept {
    uint8_t length = frame.length > kMaxDataLength ? kMaxDataLength : frame.length;
    size_t size = kCannelloniHeaderSize + 5 + (frame.remote ? 0u : length);
    if (out.size() < size) return 0;
    out[0] = kVersion;
    out[1] = kOpData;
    out[2] = sequence;
    out[3] = 0;
    out[4] = 1;
    uint32_t id =
        frame.extended ? (frame.id & kExtendedIdMask) | kEffFlag : frame.id & kStandardIdMask;
    if (frame.remote) id |= kRtrFlag;
    for (size_t i = 0; i < 4; ++i)
        out[5 + i] = static_cast<uint8_t>(id >> (24 - 8 * i));
    out[9] = length;
    if (!frame.remote) {
        for (uint8_t i = 0; i < length; ++i)
            out[10 + i] = frame.data[i];
    }
    return size;
}

int decodeCannelloni(std::span<const uint8_t> datagram, std::span<CanFrame> out) noexcept {
    if (datagram.size() < kCannelloniHeaderSize || datagram[0] != kVersion ||
        datagram[1] != kOpData) {
        return -1;
    }
    size_t count = static_cast<size_t>(datagram[3]) << 8 | datagram[4];
    size_t pos = kCannelloniHeaderSize;
    size_t decoded = 0;
    for (size_t i = 0; i < count; ++i) {
        if (pos + 5 > datagram.size()) return -1;
        uint32_t id = 0;
        for (size_t k = 0; k < 4; ++k)
            id = id << 8 | datagram[pos + k];
        uint8_t length = datagram[pos + 4];
        pos += 5;
        if ((length & kCanFdFlag) || length > kMaxDataLength || (id & kErrFlag)) return -1;
        CanFrame frame;
        frame.extended = (id & kEffFlag) != 0;
        frame.remote = (id & kRtrFlag) != 0;
        frame.id = id & (frame.extended ? kExtendedIdMask : kStandardIdMask);
        frame.length = length;
        if (!frame.remote) {
            if (pos + length > datagram.size()) return -1;
            for (uint8_t k = 0; k < length; ++k)
                frame.data[k] = datagram[pos + k];
            pos += length;
        }
        if (decoded < out.size()) out[decoded++] = frame;
    }
    return static_cast<int>(decoded);
}

}  // namespace kerf::drivers::can
