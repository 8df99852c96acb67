#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "drivers/canopen/sdo_protocol.h"

// Static PDO mapping of CiA 301: mapping entries, the layout of one PDO and little-endian
// packing of its values. A mapping entry is UINT32 index<<16 | sub-index<<8 | bit length.
// Entries are whole bytes (8, 16, 32 bits), the only lengths the drives' objects use. Pure.
namespace kerf::drivers::canopen {

struct PdoEntry {
    uint16_t index = 0;
    uint8_t subIndex = 0;
    uint8_t bits = 0;

    constexpr uint32_t value() const noexcept {
        return static_cast<uint32_t>(index) << 16 | static_cast<uint32_t>(subIndex) << 8 | bits;
    }
    static constexpr PdoEntry fromValue(uint32_t v) noexcept {
        return {static_cast<uint16_t>(v >> 16), static_cast<uint8_t>(v >> 8),
                static_cast<uint8_t>(v)};
    }
    friend constexpr bool operator==(PdoEntry, PdoEntry) = default;
};

inline constexpr uint32_t kPdoInvalid = 0x80000000u;  // COB-ID bit 31: PDO does not exist
inline constexpr uint8_t kMaxPdoEntries = 8;

struct PdoLayout {
    uint32_t cobId = 0;
    uint8_t transmissionType = 1;  // 1..240: every n-th SYNC; 254/255: event-driven
    uint16_t inhibitTime100us = 0;
    uint16_t eventTimerMs = 0;
    std::array<PdoEntry, kMaxPdoEntries> entries{};
    uint8_t count = 0;

    // Adds an entry; false when the PDO would exceed 8 entries or 64 bits.
    bool add(PdoEntry entry) noexcept;
    uint8_t byteLength() const noexcept;
    // Byte offset of the entry for `object`, or -1.
    int offsetOf(ObjectAddress object) const noexcept;
};

// Little-endian field of `bytes` bytes at `offset`.
void packField(std::span<uint8_t> data, size_t offset, size_t bytes, uint32_t value) noexcept;
uint32_t unpackField(std::span<const uint8_t> data, size_t offset, size_t bytes) noexcept;

}  // namespace kerf::drivers::canopen
