#include "core/canon/trace_printer.h"

#include <utility>

namespace kerf::canon {

namespace {
constexpr size_t kBatchCommands = 1024;
constexpr size_t kMaxQueuedBatches = 4;
constexpr size_t kWriteThreshold = 1 << 16;
}  // namespace

TracePrinter::TracePrinter(std::FILE* stream, TraceFormat format)
    : m_stream(stream), m_fileName(std::move(format.fileName)), m_format(std::move(format)) {
    m_format.fileName = [this](uint32_t fileId) { return nameOf(fileId); };
    m_batch.reserve(kBatchCommands);
    m_writer = std::thread([this] { writeBatches(); });
}

TracePrinter::~TracePrinter() {
    flush();
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_changed.notify_all();
    m_writer.join();
}

void TracePrinter::consume(const Command& command) {
    const uint32_t fileId = command.location.fileId;
    if (fileId != 0 && m_fileName && (fileId >= m_named.size() || !m_named[fileId])) {
        if (fileId >= m_named.size()) m_named.resize(fileId + 1, false);
        m_named[fileId] = true;
        std::string name = m_fileName(fileId);
        std::lock_guard lock(m_mutex);
        m_names[fileId] = std::move(name);
    }
    m_batch.push_back(command);
    if (m_batch.size() >= kBatchCommands) handOver();
}

void TracePrinter::handOver() {
    if (m_batch.empty()) return;
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_queue.size() < kMaxQueuedBatches; });
    m_queue.push_back(std::move(m_batch));
    if (m_spare.empty()) {
        m_batch = std::vector<Command>();
        m_batch.reserve(kBatchCommands);
    } else {
        m_batch = std::move(m_spare.back());
        m_spare.pop_back();
    }
    lock.unlock();
    m_changed.notify_all();
}

bool TracePrinter::flush() {
    handOver();
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_queue.empty() && !m_writing; });
    // The writer is idle and waits for the lock: the stream is ours.
    if (m_stream != nullptr && std::fflush(m_stream) != 0) m_failed = true;
    return !m_failed;
}

std::string TracePrinter::nameOf(uint32_t fileId) {
    std::lock_guard lock(m_mutex);
    auto it = m_names.find(fileId);
    return it == m_names.end() ? std::string() : it->second;
}

void TracePrinter::writeBatches() {
    std::string text;
    text.reserve(kWriteThreshold + 512);
    auto write = [&] {
        if (!text.empty() && m_stream != nullptr &&
            std::fwrite(text.data(), 1, text.size(), m_stream) != text.size()) {
            std::lock_guard lock(m_mutex);
            m_failed = true;
        }
        text.clear();
    };
    std::unique_lock lock(m_mutex);
    for (;;) {
        m_changed.wait(lock, [this] { return !m_queue.empty() || m_stop; });
        if (m_queue.empty()) return;  // stopped
        std::vector<Command> batch = std::move(m_queue.front());
        m_queue.pop_front();
        m_writing = true;
        lock.unlock();
        m_changed.notify_all();  // room in the queue
        for (const Command& command : batch) {
            appendCommand(text, command, m_format);
            text += '\n';
            if (text.size() >= kWriteThreshold) write();
        }
        batch.clear();
        lock.lock();
        // Nothing more to format: what is formatted goes out, so that flush() finds it written.
        if (m_queue.empty()) {
            lock.unlock();
            write();
            lock.lock();
        }
        m_spare.push_back(std::move(batch));
        m_writing = false;
        m_changed.notify_all();
    }
}

}  // namespace kerf::canon
