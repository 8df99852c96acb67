#pragma once

#include <vector>

#include "core/canon/commands.h"

namespace kerf::canon {

// Hands every command to several consumers in order (statistics, trace, motion ...).
class TeeSink final : public Sink {
public:
    void add(Sink& sink) { m_sinks.push_back(&sink); }
    void consume(const Command& command) override {
        for (Sink* sink : m_sinks)
            sink->consume(command);
    }

private:
    std::vector<Sink*> m_sinks;
};

}  // namespace kerf::canon
