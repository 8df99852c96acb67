#include "drivers/sim/sdo_server.h"

#include "drivers/canopen/cob_id.h"
#include "drivers/canopen/sdo_abort.h"
#include "drivers/canopen/sdo_protocol.h"

namespace kerf::drivers::sim {

namespace sdo = canopen::sdo;
using canopen::SdoAbort;

namespace {

constexpr uint32_t code(SdoAbort a) noexcept {
    return static_cast<uint32_t>(a);
}

}  // namespace

void SdoServer::abort(ObjectAddress address, uint32_t abortCode,
                      canopen::FrameOutbox& out) noexcept {
    out.push(sdo::abortTransfer(canopen::kSdoResponseBase + m_node, address, abortCode));
    m_phase = Phase::Idle;
}

uint32_t SdoServer::store(ObjectEntry& entry, std::span<const uint8_t> bytes) noexcept {
    if (!entry.writable()) return code(SdoAbort::WriteOfReadOnly);
    if (entry.type == ObjectType::String) {
        if (bytes.size() > entry.capacity()) return code(SdoAbort::LengthTooHigh);
    } else if (bytes.size() != entry.size()) {
        return code(SdoAbort::LengthMismatch);
    }
    if (uint32_t refused = m_hooks.checkWrite(entry, bytes)) return refused;
    m_od.setBytes(entry, bytes);
    m_hooks.written(entry);
    return 0;
}

void SdoServer::onRequest(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept {
    if (f.length != 8) return;  // CiA 301: SDO frames always carry 8 bytes
    switch (sdo::commandSpecifier(f)) {
        case sdo::kInitiateDownload:
            initiateDownload(f, out);
            return;
        case sdo::kDownloadSegment:
            downloadSegment(f, out);
            return;
        case sdo::kInitiateUpload:
            initiateUpload(f, out);
            return;
        case sdo::kUploadSegment:
            uploadSegment(f, out);
            return;
        case sdo::kAbort:
            m_phase = Phase::Idle;
            return;
        default:
            abort(sdo::addressOf(f), code(SdoAbort::UnknownCommand), out);
            return;
    }
}

void SdoServer::initiateDownload(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept {
    m_phase = Phase::Idle;
    ObjectAddress a = sdo::addressOf(f);
    if (uint32_t injected = m_hooks.accessAbort(a)) return abort(a, injected, out);
    ObjectEntry* entry = m_od.find(a);
    if (!entry) {
        return abort(a, code(m_od.hasIndex(a.index) ? SdoAbort::NoSubIndex : SdoAbort::NoObject),
                     out);
    }
    bool expedited = (f.data[0] & 0x02) != 0;
    bool sized = (f.data[0] & 0x01) != 0;
    if (expedited) {
        size_t size = sized ? 4u - ((f.data[0] >> 2) & 0x03u) : entry->size();
        if (uint32_t refused = store(*entry, {f.data.data() + 4, size}))
            return abort(a, refused, out);
        out.push(sdo::downloadResponse(m_node, a));
        return;
    }
    if (!entry->writable()) return abort(a, code(SdoAbort::WriteOfReadOnly), out);
    uint32_t size = sized ? sdo::u32At(f, 4) : static_cast<uint32_t>(entry->capacity());
    if (size > entry->capacity()) return abort(a, code(SdoAbort::LengthTooHigh), out);
    m_phase = Phase::Downloading;
    m_address = a;
    m_size = size;
    m_offset = 0;
    m_toggle = false;
    out.push(sdo::downloadResponse(m_node, a));
}

void SdoServer::downloadSegment(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept {
    if (m_phase != Phase::Downloading) return abort({}, code(SdoAbort::UnknownCommand), out);
    if (sdo::toggleOf(f) != m_toggle) return abort(m_address, code(SdoAbort::ToggleBit), out);
    size_t count = sdo::kSegmentBytes - ((f.data[0] >> 1) & 0x07u);
    if (m_offset + count > m_buffer.size())
        return abort(m_address, code(SdoAbort::LengthTooHigh), out);
    for (size_t i = 0; i < count; ++i)
        m_buffer[m_offset + i] = f.data[1 + i];
    m_offset += count;
    bool last = (f.data[0] & 0x01) != 0;
    if (last) {
        m_phase = Phase::Idle;
        ObjectEntry* entry = m_od.find(m_address);
        if (m_offset != m_size) return abort(m_address, code(SdoAbort::LengthMismatch), out);
        if (uint32_t refused = store(*entry, {m_buffer.data(), m_offset})) {
            return abort(m_address, refused, out);
        }
    }
    out.push(sdo::downloadSegmentResponse(m_node, m_toggle));
    m_toggle = !m_toggle;
}

void SdoServer::initiateUpload(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept {
    m_phase = Phase::Idle;
    ObjectAddress a = sdo::addressOf(f);
    if (uint32_t injected = m_hooks.accessAbort(a)) return abort(a, injected, out);
    const ObjectEntry* entry = m_od.find(a);
    if (!entry) {
        return abort(a, code(m_od.hasIndex(a.index) ? SdoAbort::NoSubIndex : SdoAbort::NoObject),
                     out);
    }
    if (!entry->readable()) return abort(a, code(SdoAbort::ReadOfWriteOnly), out);
    size_t size = m_od.getBytes(*entry, m_buffer);
    if (size > 0 && size <= 4) {
        out.push(sdo::expeditedUploadResponse(m_node, a, {m_buffer.data(), size}));
        return;
    }
    m_phase = Phase::Uploading;
    m_address = a;
    m_size = size;
    m_offset = 0;
    m_toggle = false;
    out.push(sdo::segmentedUploadResponse(m_node, a, static_cast<uint32_t>(size)));
}

void SdoServer::uploadSegment(const can::CanFrame& f, canopen::FrameOutbox& out) noexcept {
    if (m_phase != Phase::Uploading) return abort({}, code(SdoAbort::UnknownCommand), out);
    if (sdo::toggleOf(f) != m_toggle) return abort(m_address, code(SdoAbort::ToggleBit), out);
    size_t count = m_size - m_offset > sdo::kSegmentBytes ? sdo::kSegmentBytes : m_size - m_offset;
    bool last = m_offset + count == m_size;
    out.push(sdo::uploadSegment(m_node, m_toggle, {m_buffer.data() + m_offset, count}, last));
    m_offset += count;
    m_toggle = !m_toggle;
    if (last) m_phase = Phase::Idle;
}

}  // namespace kerf::drivers::sim
