#include "drivers/canopen/sdo_client.h"

#include "drivers/canopen/cob_id.h"
#include "drivers/canopen/sdo_abort.h"

namespace kerf::drivers::canopen {

void SdoClient::configure(uint8_t node, std::chrono::nanoseconds timeout) noexcept {
    m_node = node;
    m_timeout = timeout;
    m_status = SdoStatus::Idle;
}

bool SdoClient::download(ObjectAddress address, std::span<const uint8_t> data,
                         std::chrono::nanoseconds now, FrameOutbox& out) noexcept {
    if (m_status == SdoStatus::Busy || data.size() > kMaxData || data.empty()) return false;
    m_status = SdoStatus::Busy;
    m_error.clear();
    m_address = address;
    m_size = data.size();
    m_offset = 0;
    for (size_t i = 0; i < data.size(); ++i)
        m_data[i] = data[i];
    m_phase = Phase::InitiateDownload;
    if (m_size <= 4) {
        out.push(sdo::expeditedDownload(m_node, address, data));
        m_offset = m_size;
    } else {
        out.push(sdo::initiateSegmentedDownload(m_node, address, static_cast<uint32_t>(m_size)));
    }
    sent(now);
    return true;
}

bool SdoClient::upload(ObjectAddress address, std::chrono::nanoseconds now,
                       FrameOutbox& out) noexcept {
    if (m_status == SdoStatus::Busy) return false;
    m_status = SdoStatus::Busy;
    m_error.clear();
    m_address = address;
    m_size = 0;
    m_phase = Phase::InitiateUpload;
    out.push(sdo::initiateUpload(m_node, address));
    sent(now);
    return true;
}

uint32_t SdoClient::value() const noexcept {
    uint32_t v = 0;
    for (size_t i = m_size < 4 ? m_size : 4; i > 0; --i)
        v = v << 8 | m_data[i - 1];
    return v;
}

void SdoClient::acknowledge() noexcept {
    if (m_status != SdoStatus::Busy) m_status = SdoStatus::Idle;
}

void SdoClient::cancel() noexcept {
    m_status = SdoStatus::Idle;
}

void SdoClient::fail(std::error_code error, bool sendAbort, FrameOutbox& out) noexcept {
    if (sendAbort) {
        out.push(sdo::abortTransfer(kSdoRequestBase + m_node, m_address, abortCodeOf(error)));
    }
    m_error = error;
    m_status = SdoStatus::Failed;
}

void SdoClient::sendNextSegment(FrameOutbox& out) noexcept {
    size_t count = m_size - m_offset > sdo::kSegmentBytes ? sdo::kSegmentBytes : m_size - m_offset;
    bool last = m_offset + count == m_size;
    out.push(sdo::downloadSegment(m_node, m_toggle, {m_data.data() + m_offset, count}, last));
    m_offset += count;
}

void SdoClient::onFrame(const can::CanFrame& f, std::chrono::nanoseconds now,
                        FrameOutbox& out) noexcept {
    if (m_status != SdoStatus::Busy || f.length != 8) return;
    uint8_t scs = sdo::commandSpecifier(f);
    if (scs == sdo::kAbort) {
        if (sdo::addressOf(f) == m_address) fail(sdoError(sdo::u32At(f, 4)), false, out);
        return;
    }
    switch (m_phase) {
        case Phase::InitiateDownload:
            if (scs != sdo::kInitiateDownloadResponse || !(sdo::addressOf(f) == m_address)) break;
            if (m_offset == m_size) {
                m_status = SdoStatus::Done;
                return;
            }
            m_phase = Phase::DownloadSegment;
            m_toggle = false;
            sendNextSegment(out);
            sent(now);
            return;
        case Phase::DownloadSegment:
            if (scs != sdo::kDownloadSegmentResponse) break;
            if (sdo::toggleOf(f) != m_toggle) {
                fail(SdoAbort::ToggleBit, true, out);
                return;
            }
            if (m_offset == m_size) {
                m_status = SdoStatus::Done;
                return;
            }
            m_toggle = !m_toggle;
            sendNextSegment(out);
            sent(now);
            return;
        case Phase::InitiateUpload: {
            if (scs != sdo::kInitiateUploadResponse || !(sdo::addressOf(f) == m_address)) break;
            bool expedited = (f.data[0] & 0x02) != 0;
            bool sized = (f.data[0] & 0x01) != 0;
            if (expedited) {
                // Without the size bit the server leaves the size open: take all four bytes.
                m_size = sized ? 4u - ((f.data[0] >> 2) & 0x03u) : 4u;
                for (size_t i = 0; i < m_size; ++i)
                    m_data[i] = f.data[4 + i];
                m_status = SdoStatus::Done;
                return;
            }
            if (sized && sdo::u32At(f, 4) > kMaxData) {
                fail(SdoAbort::OutOfMemory, true, out);
                return;
            }
            m_phase = Phase::UploadSegment;
            m_toggle = false;
            out.push(sdo::uploadSegmentRequest(m_node, m_toggle));
            sent(now);
            return;
        }
        case Phase::UploadSegment: {
            if (scs != sdo::kUploadSegmentResponse) break;
            if (sdo::toggleOf(f) != m_toggle) {
                fail(SdoAbort::ToggleBit, true, out);
                return;
            }
            size_t count = sdo::kSegmentBytes - ((f.data[0] >> 1) & 0x07u);
            if (m_size + count > kMaxData) {
                fail(SdoAbort::OutOfMemory, true, out);
                return;
            }
            for (size_t i = 0; i < count; ++i)
                m_data[m_size + i] = f.data[1 + i];
            m_size += count;
            if (f.data[0] & 0x01) {
                m_status = SdoStatus::Done;
                return;
            }
            m_toggle = !m_toggle;
            out.push(sdo::uploadSegmentRequest(m_node, m_toggle));
            sent(now);
            return;
        }
    }
    fail(SdoAbort::UnknownCommand, true, out);
}

void SdoClient::advance(std::chrono::nanoseconds now, FrameOutbox& out) noexcept {
    if (m_status == SdoStatus::Busy && now >= m_deadline) fail(SdoAbort::Timeout, true, out);
}

}  // namespace kerf::drivers::canopen
