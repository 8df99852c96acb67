#include "core/canon/trace_printer.h"

namespace kerf::canon {

namespace {
constexpr size_t kFlushThreshold = 1 << 16;
}

TracePrinter::TracePrinter(std::FILE* stream, TraceFormat format)
    : m_stream(stream), m_format(std::move(format)) {
    m_buffer.reserve(kFlushThreshold + 512);
}

TracePrinter::~TracePrinter() {
    flush();
}

void TracePrinter::consume(const Command& command) {
    appendCommand(m_buffer, command, m_format);
    m_buffer += '\n';
    if (m_buffer.size() >= kFlushThreshold) flush();
}

bool TracePrinter::flush() {
    if (!m_buffer.empty() && m_stream != nullptr) {
        if (std::fwrite(m_buffer.data(), 1, m_buffer.size(), m_stream) != m_buffer.size()) {
            m_failed = true;
        }
    }
    m_buffer.clear();
    if (m_stream != nullptr && std::fflush(m_stream) != 0) m_failed = true;
    return !m_failed;
}

}  // namespace kerf::canon
