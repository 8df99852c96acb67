#pragma once

#include <cstdint>

// Identifiers of the CiA 301 predefined connection set (11-bit): function code + node-ID 1..127.
namespace kerf::drivers::canopen {

inline constexpr uint32_t kNmtId = 0x000;
inline constexpr uint32_t kSyncId = 0x080;
inline constexpr uint32_t kEmcyBase = 0x080;
inline constexpr uint32_t kTpdo1Base = 0x180;
inline constexpr uint32_t kRpdo1Base = 0x200;
inline constexpr uint32_t kSdoResponseBase = 0x580;
inline constexpr uint32_t kSdoRequestBase = 0x600;
inline constexpr uint32_t kHeartbeatBase = 0x700;
inline constexpr uint8_t kMaxNodeId = 127;

// PDO number 1..4 of a node.
constexpr uint32_t tpdoCobId(int number, uint8_t node) noexcept {
    return kTpdo1Base + 0x100u * static_cast<uint32_t>(number - 1) + node;
}
constexpr uint32_t rpdoCobId(int number, uint8_t node) noexcept {
    return kRpdo1Base + 0x100u * static_cast<uint32_t>(number - 1) + node;
}

constexpr uint32_t functionCode(uint32_t cobId) noexcept {
    return cobId & 0x780;
}
constexpr uint8_t nodeOf(uint32_t cobId) noexcept {
    return static_cast<uint8_t>(cobId & 0x7F);
}

}  // namespace kerf::drivers::canopen
