#pragma once

#include <cstdio>
#include <string>

#include "core/canon/trace_format.h"

namespace kerf::canon {

// Sink that writes the trace, one line per command, to a stdio stream through a large buffer.
class TracePrinter final : public Sink {
public:
    TracePrinter(std::FILE* stream, TraceFormat format);
    ~TracePrinter() override;
    TracePrinter(const TracePrinter&) = delete;
    TracePrinter& operator=(const TracePrinter&) = delete;

    void consume(const Command& command) override;
    // Writes what is buffered; false if the stream reported an error.
    bool flush();

private:
    std::FILE* m_stream;
    TraceFormat m_format;
    std::string m_buffer;
    bool m_failed = false;
};

}  // namespace kerf::canon
