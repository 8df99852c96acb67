#include "drivers/sim/object_dictionary.h"

#include <algorithm>

namespace kerf::drivers::sim {

namespace {

bool before(const ObjectEntry& e, ObjectAddress a) noexcept {
    return e.address.index != a.index ? e.address.index < a.index : e.address.subIndex < a.subIndex;
}

uint32_t widthMask(ObjectType type) noexcept {
    switch (typeSize(type)) {
        case 1:
            return 0xFFu;
        case 2:
            return 0xFFFFu;
        default:
            return 0xFFFFFFFFu;
    }
}

}  // namespace

size_t typeSize(ObjectType type) noexcept {
    switch (type) {
        case ObjectType::U8:
        case ObjectType::I8:
            return 1;
        case ObjectType::U16:
        case ObjectType::I16:
            return 2;
        case ObjectType::U32:
        case ObjectType::I32:
            return 4;
        case ObjectType::String:
            return 0;
    }
    return 0;
}

size_t ObjectEntry::size() const noexcept {
    return type == ObjectType::String ? textLength : typeSize(type);
}

size_t ObjectEntry::capacity() const noexcept {
    return type == ObjectType::String ? kTextCapacity : typeSize(type);
}

int32_t ObjectEntry::asSigned() const noexcept {
    switch (type) {
        case ObjectType::I8:
            return static_cast<int8_t>(value & 0xFF);
        case ObjectType::I16:
            return static_cast<int16_t>(value & 0xFFFF);
        default:
            return static_cast<int32_t>(value);
    }
}

void ObjectDictionary::add(ObjectAddress address, ObjectType type, Access access, uint32_t value,
                           Mapping mapping) {
    ObjectEntry entry;
    entry.address = address;
    entry.type = type;
    entry.access = access;
    entry.mapping = mapping;
    entry.value = value & widthMask(type);
    auto it = std::lower_bound(m_entries.begin(), m_entries.end(), address, before);
    if (it != m_entries.end() && it->address == address) {
        *it = entry;
    } else {
        m_entries.insert(it, entry);
    }
}

void ObjectDictionary::addText(ObjectAddress address, Access access, std::string_view text) {
    add(address, ObjectType::String, access, 0);
    ObjectEntry* e = find(address);
    e->textLength = std::min(text.size(), ObjectEntry::kTextCapacity);
    std::copy_n(text.begin(), e->textLength, e->text.begin());
}

ObjectEntry* ObjectDictionary::find(ObjectAddress address) noexcept {
    auto it = std::lower_bound(m_entries.begin(), m_entries.end(), address, before);
    return it != m_entries.end() && it->address == address ? &*it : nullptr;
}

const ObjectEntry* ObjectDictionary::find(ObjectAddress address) const noexcept {
    return const_cast<ObjectDictionary*>(this)->find(address);
}

bool ObjectDictionary::hasIndex(uint16_t index) const noexcept {
    auto it = std::lower_bound(m_entries.begin(), m_entries.end(), ObjectAddress{index, 0}, before);
    return it != m_entries.end() && it->address.index == index;
}

uint32_t ObjectDictionary::get(ObjectAddress address) const noexcept {
    const ObjectEntry* e = find(address);
    return e ? e->value : 0;
}

int32_t ObjectDictionary::getSigned(ObjectAddress address) const noexcept {
    const ObjectEntry* e = find(address);
    return e ? e->asSigned() : 0;
}

void ObjectDictionary::set(ObjectAddress address, uint32_t value) noexcept {
    if (ObjectEntry* e = find(address)) e->value = value & widthMask(e->type);
}

void ObjectDictionary::setBytes(ObjectEntry& entry, std::span<const uint8_t> bytes) noexcept {
    if (entry.type == ObjectType::String) {
        entry.textLength = std::min(bytes.size(), ObjectEntry::kTextCapacity);
        std::copy_n(bytes.begin(), entry.textLength, entry.text.begin());
        return;
    }
    uint32_t value = 0;
    for (size_t i = std::min<size_t>(bytes.size(), 4); i > 0; --i)
        value = value << 8 | bytes[i - 1];
    entry.value = value & widthMask(entry.type);
}

size_t ObjectDictionary::getBytes(const ObjectEntry& entry, std::span<uint8_t> out) const noexcept {
    size_t size = std::min(entry.size(), out.size());
    if (entry.type == ObjectType::String) {
        std::copy_n(entry.text.begin(), size, out.begin());
    } else {
        for (size_t i = 0; i < size; ++i)
            out[i] = static_cast<uint8_t>(entry.value >> (8 * i));
    }
    return size;
}

}  // namespace kerf::drivers::sim
