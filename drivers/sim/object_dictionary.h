#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "drivers/canopen/sdo_protocol.h"

// The object dictionary of a simulated drive: typed entries (CiA 301 basic types and short
// visible strings) with access rights and PDO mapping direction. Built by add() before the
// simulation; lookups by binary search, reads and writes of values without allocation.
namespace kerf::drivers::sim {

using canopen::ObjectAddress;

enum class ObjectType : uint8_t { U8, I8, U16, I16, U32, I32, String };
enum class Access : uint8_t { ReadOnly, ReadWrite, WriteOnly };
enum class Mapping : uint8_t { None, Receive, Transmit };  // RPDO or TPDO mappable

struct ObjectEntry {
    static constexpr size_t kTextCapacity = 48;

    ObjectAddress address;
    ObjectType type = ObjectType::U32;
    Access access = Access::ReadOnly;
    Mapping mapping = Mapping::None;
    uint32_t value = 0;  // the bits of numeric types, zero-extended
    std::array<uint8_t, kTextCapacity> text{};
    size_t textLength = 0;

    // Bytes of the value (strings: their current length).
    size_t size() const noexcept;
    size_t capacity() const noexcept;   // strings: kTextCapacity; numbers: size()
    int32_t asSigned() const noexcept;  // sign-extends I8/I16
    bool readable() const noexcept { return access != Access::WriteOnly; }
    bool writable() const noexcept { return access != Access::ReadOnly; }
};

class ObjectDictionary {
public:
    // Construction: adds (or replaces) an entry.
    void add(ObjectAddress address, ObjectType type, Access access, uint32_t value,
             Mapping mapping = Mapping::None);
    void addText(ObjectAddress address, Access access, std::string_view text);

    ObjectEntry* find(ObjectAddress address) noexcept;
    const ObjectEntry* find(ObjectAddress address) const noexcept;
    bool hasIndex(uint16_t index) const noexcept;

    // Internal access of the device (no rights checked); 0 for a missing entry.
    uint32_t get(ObjectAddress address) const noexcept;
    int32_t getSigned(ObjectAddress address) const noexcept;
    void set(ObjectAddress address, uint32_t value) noexcept;
    // Copies bytes into an entry (strings) or sets a number from little-endian bytes.
    void setBytes(ObjectEntry& entry, std::span<const uint8_t> bytes) noexcept;
    // The value's bytes, little-endian for numbers; returns how many.
    size_t getBytes(const ObjectEntry& entry, std::span<uint8_t> out) const noexcept;

private:
    std::vector<ObjectEntry> m_entries;  // sorted by index, then sub-index
};

size_t typeSize(ObjectType type) noexcept;

}  // namespace kerf::drivers::sim
