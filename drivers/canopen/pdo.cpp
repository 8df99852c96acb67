#include "drivers/canopen/pdo.h"

namespace kerf::drivers::canopen {

bool PdoLayout::add(PdoEntry entry) noexcept {
    if (count == kMaxPdoEntries || entry.bits % 8 != 0 || entry.bits == 0 ||
        byteLength() + entry.bits / 8 > 8) {
        return false;
    }
    entries[count++] = entry;
    return true;
}

uint8_t PdoLayout::byteLength() const noexcept {
    unsigned bytes = 0;
    for (uint8_t i = 0; i < count; ++i)
        bytes += entries[i].bits / 8u;
    return static_cast<uint8_t>(bytes);
}

int PdoLayout::offsetOf(ObjectAddress object) const noexcept {
    int offset = 0;
    for (uint8_t i = 0; i < count; ++i) {
        if (entries[i].index == object.index && entries[i].subIndex == object.subIndex)
            return offset;
        offset += entries[i].bits / 8;
    }
    return -1;
}

void packField(std::span<uint8_t> data, size_t offset, size_t bytes, uint32_t value) noexcept {
    for (size_t i = 0; i < bytes && offset + i < data.size(); ++i)
        data[offset + i] = static_cast<uint8_t>(value >> (8 * i));
}

uint32_t unpackField(std::span<const uint8_t> data, size_t offset, size_t bytes) noexcept {
    uint32_t value = 0;
    for (size_t i = bytes; i > 0; --i)
        value = value << 8 | (offset + i - 1 < data.size() ? data[offset + i - 1] : 0u);
    return value;
}

}  // namespace kerf::drivers::canopen
