#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "drivers/can/can_frame.h"
#include "drivers/canopen/frame_outbox.h"
#include "drivers/sim/object_dictionary.h"

// The SDO server of a simulated node (CiA 301 7.2.4): expedited and segmented upload and
// download with the standard abort codes; the device checks and applies writes through
// SdoServerHooks. One request in, at most one response out. Simulation thread; no allocation.
namespace kerf::drivers::sim {

class SdoServerHooks {
public:
    virtual ~SdoServerHooks() = default;
    // 0 or the abort code for accessing `address` at all (fault injection).
    virtual uint32_t accessAbort(ObjectAddress address) noexcept = 0;
    // 0 or the abort code that refuses writing `bytes` into `entry`.
    virtual uint32_t checkWrite(const ObjectEntry& entry,
                                std::span<const uint8_t> bytes) noexcept = 0;
    // After a write was stored.
    virtual void written(const ObjectEntry& entry) noexcept = 0;
};

class SdoServer {
public:
    SdoServer(ObjectDictionary& dictionary, SdoServerHooks& hooks)
        : m_od(dictionary), m_hooks(hooks) {}
    void setNode(uint8_t node) noexcept { m_node = node; }
    // A request from 0x600 + node; the response goes into `out`.
    void onRequest(const can::CanFrame& request, canopen::FrameOutbox& out) noexcept;
    void reset() noexcept { m_phase = Phase::Idle; }

private:
    enum class Phase : uint8_t { Idle, Downloading, Uploading };

    void abort(ObjectAddress address, uint32_t code, canopen::FrameOutbox& out) noexcept;
    void initiateDownload(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept;
    void downloadSegment(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept;
    void initiateUpload(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept;
    void uploadSegment(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept;
    // Checks rights and size, stores, tells the device; 0 or an abort code.
    uint32_t store(ObjectEntry& entry, std::span<const uint8_t> bytes) noexcept;

    ObjectDictionary& m_od;
    SdoServerHooks& m_hooks;
    uint8_t m_node = 0;
    Phase m_phase = Phase::Idle;
    ObjectAddress m_address;
    std::array<uint8_t, ObjectEntry::kTextCapacity> m_buffer{};
    size_t m_size = 0;    // download: announced size; upload: bytes to send
    size_t m_offset = 0;  // bytes transferred
    bool m_toggle = false;
};

}  // namespace kerf::drivers::sim
