#include "drivers/canopen/sdo_protocol.h"

#include "drivers/canopen/cob_id.h"

namespace kerf::drivers::canopen::sdo {

namespace {

can::CanFrame frameWith(uint32_t id, uint8_t command, ObjectAddress a) noexcept {
    can::CanFrame f;
    f.id = id;
    f.length = 8;
    f.data[0] = command;
    f.data[1] = static_cast<uint8_t>(a.index & 0xFF);
    f.data[2] = static_cast<uint8_t>(a.index >> 8);
    f.data[3] = a.subIndex;
    return f;
}

void putU32(can::CanFrame& f, uint32_t value) noexcept {
    for (int i = 0; i < 4; ++i)
        f.data[static_cast<size_t>(4 + i)] = static_cast<uint8_t>(value >> (8 * i));
}

// An expedited frame: n = bytes 4-7 that hold no data, e = 1, s = 1.
can::CanFrame expedited(uint32_t id, uint8_t specifier, ObjectAddress a,
                        std::span<const uint8_t> data) noexcept {
    size_t size = data.size() > 4 ? 4 : data.size();
    auto unused = static_cast<uint8_t>(4 - size);
    can::CanFrame f = frameWith(id, static_cast<uint8_t>(specifier << 5 | unused << 2 | 0x03), a);
    for (size_t i = 0; i < size; ++i)
        f.data[4 + i] = data[i];
    return f;
}

// A segment: t = toggle, n = bytes 1-7 that hold no data, c = last segment.
can::CanFrame segment(uint32_t id, uint8_t specifier, bool toggle, std::span<const uint8_t> data,
                      bool last) noexcept {
    size_t size = data.size() > kSegmentBytes ? kSegmentBytes : data.size();
    can::CanFrame f;
    f.id = id;
    f.length = 8;
    f.data[0] = static_cast<uint8_t>(specifier << 5 | (toggle ? 0x10 : 0) |
                                     (kSegmentBytes - size) << 1 | (last ? 1 : 0));
    for (size_t i = 0; i < size; ++i)
        f.data[1 + i] = data[i];
    return f;
}

}  // namespace

ObjectAddress addressOf(const can::CanFrame& frame) noexcept {
    return {static_cast<uint16_t>(frame.data[1] | frame.data[2] << 8), frame.data[3]};
}

uint32_t u32At(const can::CanFrame& frame, int offset) noexcept {
    uint32_t value = 0;
    for (int i = 3; i >= 0; --i)
        value = value << 8 | frame.data[static_cast<size_t>(offset + i)];
    return value;
}

can::CanFrame expeditedDownload(uint8_t node, ObjectAddress a,
                                std::span<const uint8_t> data) noexcept {
    return expedited(kSdoRequestBase + node, kInitiateDownload, a, data);
}

can::CanFrame initiateSegmentedDownload(uint8_t node, ObjectAddress a, uint32_t size) noexcept {
    can::CanFrame f = frameWith(kSdoRequestBase + node, kInitiateDownload << 5 | 0x01, a);
    putU32(f, size);
    return f;
}

can::CanFrame downloadSegment(uint8_t node, bool toggle, std::span<const uint8_t> data,
                              bool last) noexcept {
    return segment(kSdoRequestBase + node, kDownloadSegment, toggle, data, last);
}

can::CanFrame initiateUpload(uint8_t node, ObjectAddress a) noexcept {
    return frameWith(kSdoRequestBase + node, kInitiateUpload << 5, a);
}

can::CanFrame uploadSegmentRequest(uint8_t node, bool toggle) noexcept {
    can::CanFrame f;
    f.id = kSdoRequestBase + node;
    f.length = 8;
    f.data[0] = static_cast<uint8_t>(kUploadSegment << 5 | (toggle ? 0x10 : 0));
    return f;
}

can::CanFrame downloadResponse(uint8_t node, ObjectAddress a) noexcept {
    return frameWith(kSdoResponseBase + node, kInitiateDownloadResponse << 5, a);
}

can::CanFrame downloadSegmentResponse(uint8_t node, bool toggle) noexcept {
    can::CanFrame f;
    f.id = kSdoResponseBase + node;
    f.length = 8;
    f.data[0] = static_cast<uint8_t>(kDownloadSegmentResponse << 5 | (toggle ? 0x10 : 0));
    return f;
}

can::CanFrame expeditedUploadResponse(uint8_t node, ObjectAddress a,
                                      std::span<const uint8_t> data) noexcept {
    return expedited(kSdoResponseBase + node, kInitiateUploadResponse, a, data);
}

can::CanFrame segmentedUploadResponse(uint8_t node, ObjectAddress a, uint32_t size) noexcept {
    can::CanFrame f = frameWith(kSdoResponseBase + node, kInitiateUploadResponse << 5 | 0x01, a);
    putU32(f, size);
    return f;
}

can::CanFrame uploadSegment(uint8_t node, bool toggle, std::span<const uint8_t> data,
                            bool last) noexcept {
    return segment(kSdoResponseBase + node, kUploadSegmentResponse, toggle, data, last);
}

can::CanFrame abortTransfer(uint32_t cobId, ObjectAddress a, uint32_t abortCode) noexcept {
    can::CanFrame f = frameWith(cobId, kAbort << 5, a);
    putU32(f, abortCode);
    return f;
}

}  // namespace kerf::drivers::canopen::sdo
