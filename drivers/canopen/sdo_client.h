#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <span>
#include <system_error>

#include "drivers/can/can_frame.h"
#include "drivers/canopen/frame_outbox.h"
#include "drivers/canopen/sdo_protocol.h"

// The SDO client of one server node: one transfer at a time, expedited (up to 4 bytes) or
// segmented (up to kMaxData bytes), in both directions, with a response timeout. Failures are
// std::error_code values: an abort code from the server or SdoAbort::Timeout (the client then
// sends the abort itself), all in the "canopen.sdo" category. Passive: the owner passes the
// server's responses to onFrame() and calls advance() every cycle; frames to send go into the
// given outbox. Cycle thread only; noexcept, no allocation.
namespace kerf::drivers::canopen {

enum class SdoStatus : uint8_t { Idle, Busy, Done, Failed };

class SdoClient {
public:
    static constexpr size_t kMaxData = 256;

    void configure(uint8_t node, std::chrono::nanoseconds timeout) noexcept;
    uint8_t node() const noexcept { return m_node; }

    // Start a transfer; false while another one is busy or the data is too long.
    bool download(ObjectAddress address, std::span<const uint8_t> data,
                  std::chrono::nanoseconds now, FrameOutbox& out) noexcept;
    bool upload(ObjectAddress address, std::chrono::nanoseconds now, FrameOutbox& out) noexcept;

    // A frame from 0x580 + node.
    void onFrame(const can::CanFrame& frame, std::chrono::nanoseconds now,
                 FrameOutbox& out) noexcept;
    // Response timeout.
    void advance(std::chrono::nanoseconds now, FrameOutbox& out) noexcept;

    SdoStatus status() const noexcept { return m_status; }
    std::error_code error() const noexcept { return m_error; }
    // Uploaded bytes once status() == Done.
    std::span<const uint8_t> data() const noexcept { return {m_data.data(), m_size}; }
    // Little-endian value of the uploaded bytes (up to 4).
    uint32_t value() const noexcept;
    // Back to Idle after the owner took the result of a Done or Failed transfer.
    void acknowledge() noexcept;
    // Drops a transfer without a word to the server (the node is being reset).
    void cancel() noexcept;

private:
    enum class Phase : uint8_t { InitiateDownload, DownloadSegment, InitiateUpload, UploadSegment };

    void sendNextSegment(FrameOutbox& out) noexcept;
    void fail(std::error_code error, bool sendAbort, FrameOutbox& out) noexcept;
    void sent(std::chrono::nanoseconds now) noexcept { m_deadline = now + m_timeout; }

    uint8_t m_node = 0;
    std::chrono::nanoseconds m_timeout{std::chrono::milliseconds(200)};
    SdoStatus m_status = SdoStatus::Idle;
    Phase m_phase = Phase::InitiateDownload;
    ObjectAddress m_address;
    std::array<uint8_t, kMaxData> m_data{};
    size_t m_size = 0;    // bytes to download / uploaded so far
    size_t m_offset = 0;  // download: bytes sent
    bool m_toggle = false;
    std::chrono::nanoseconds m_deadline{0};
    std::error_code m_error;
};

}  // namespace kerf::drivers::canopen
