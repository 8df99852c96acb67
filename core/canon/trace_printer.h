#pragma once

#include <condition_variable>
#include <cstdio>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/canon/trace_format.h"

namespace kerf::canon {

// Sink that writes the trace, one line per command, to a stdio stream. Formatting the lines is
// about a quarter of a plain program's run, so it happens on a thread of its own: consume()
// copies the command into a batch, and full batches go to the writer through a short queue
// (memory stays flat: the caller waits when the writer is that far behind).
class TracePrinter final : public Sink {
public:
    TracePrinter(std::FILE* stream, TraceFormat format);
    ~TracePrinter() override;
    TracePrinter(const TracePrinter&) = delete;
    TracePrinter& operator=(const TracePrinter&) = delete;

    void consume(const Command& command) override;
    // Writes everything consumed so far; false if the stream reported an error.
    bool flush();

private:
    void handOver();  // queues m_batch
    void writeBatches();
    std::string nameOf(uint32_t fileId);

    std::FILE* m_stream;
    // The caller's file names, asked on the caller's thread: the registry behind them grows
    // while the program runs.
    std::function<std::string(uint32_t)> m_fileName;
    std::vector<bool> m_named;  // file ids whose name is in m_names (caller's thread)
    TraceFormat m_format;       // the writer's: names from m_names
    std::vector<Command> m_batch;

    std::mutex m_mutex;  // guards everything below
    std::condition_variable m_changed;
    std::deque<std::vector<Command>> m_queue;
    std::vector<std::vector<Command>> m_spare;  // written batches, kept for their capacity
    std::map<uint32_t, std::string> m_names;
    bool m_writing = false;  // the writer holds a batch
    bool m_stop = false;
    bool m_failed = false;
    std::thread m_writer;
};

}  // namespace kerf::canon
