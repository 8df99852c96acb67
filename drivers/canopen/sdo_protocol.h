#pragma once

#include <cstdint>
#include <span>

#include "drivers/can/can_frame.h"

// SDO frames of CiA 301 (7.2.4.3), shared by the client (master) and the server (simulated
// drive): requests go to 0x600 + node, responses to 0x580 + node, always 8 bytes; byte 0 is the
// command specifier, bytes 1-2 the index (little-endian), byte 3 the sub-index. Pure, any thread.
namespace kerf::drivers::canopen {

struct ObjectAddress {
    uint16_t index = 0;
    uint8_t subIndex = 0;
    friend constexpr bool operator==(ObjectAddress, ObjectAddress) = default;
};

namespace sdo {

// Client command specifiers (bits 7-5 of byte 0 in a request).
inline constexpr uint8_t kDownloadSegment = 0;
inline constexpr uint8_t kInitiateDownload = 1;
inline constexpr uint8_t kInitiateUpload = 2;
inline constexpr uint8_t kUploadSegment = 3;
inline constexpr uint8_t kAbort = 4;
// Server command specifiers (bits 7-5 of byte 0 in a response).
inline constexpr uint8_t kUploadSegmentResponse = 0;
inline constexpr uint8_t kDownloadSegmentResponse = 1;
inline constexpr uint8_t kInitiateUploadResponse = 2;
inline constexpr uint8_t kInitiateDownloadResponse = 3;

inline constexpr uint8_t kSegmentBytes = 7;

constexpr uint8_t commandSpecifier(const can::CanFrame& f) noexcept {
    return f.data[0] >> 5;
}
constexpr bool toggleOf(const can::CanFrame& f) noexcept {
    return (f.data[0] & 0x10) != 0;
}
ObjectAddress addressOf(const can::CanFrame& frame) noexcept;
uint32_t u32At(const can::CanFrame& frame, int offset) noexcept;

// Requests (client -> server).
can::CanFrame expeditedDownload(uint8_t node, ObjectAddress a,
                                std::span<const uint8_t> data) noexcept;
can::CanFrame initiateSegmentedDownload(uint8_t node, ObjectAddress a, uint32_t size) noexcept;
can::CanFrame downloadSegment(uint8_t node, bool toggle, std::span<const uint8_t> data,
                              bool last) noexcept;
can::CanFrame initiateUpload(uint8_t node, ObjectAddress a) noexcept;
can::CanFrame uploadSegmentRequest(uint8_t node, bool toggle) noexcept;

// Responses (server -> client).
can::CanFrame downloadResponse(uint8_t node, ObjectAddress a) noexcept;
can::CanFrame downloadSegmentResponse(uint8_t node, bool toggle) noexcept;
can::CanFrame expeditedUploadResponse(uint8_t node, ObjectAddress a,
                                      std::span<const uint8_t> data) noexcept;
can::CanFrame segmentedUploadResponse(uint8_t node, ObjectAddress a, uint32_t size) noexcept;
can::CanFrame uploadSegment(uint8_t node, bool toggle, std::span<const uint8_t> data,
                            bool last) noexcept;

// Either direction: cobId is 0x600 + node (client aborts) or 0x580 + node (server aborts).
can::CanFrame abortTransfer(uint32_t cobId, ObjectAddress a, uint32_t abortCode) noexcept;

}  // namespace sdo
}  // namespace kerf::drivers::canopen
