#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/base/diagnostic.h"
#include "core/canon/path_statistics.h"
#include "core/machine/machine_config.h"

namespace kerf::app {

// Follows the lathe's X display mode through the stream (G151/G152).
class DisplayModeTracker final : public canon::Sink {
public:
    explicit DisplayModeTracker(bool xInDiameter) : m_diameter(xInDiameter) {}
    void consume(const canon::Command& command) override {
        if (const auto* mode = std::get_if<canon::DiameterMode>(&command.body)) {
            m_diameter = mode->xInDiameter;
        }
    }
    bool xInDiameter() const { return m_diameter; }

private:
    bool m_diameter;
};

struct RunSummary {
    bool ok = false;
    std::string dialect;
    DiagnosticList diagnostics;
    uint64_t blocksExecuted = 0;
    bool xInDiameter = false;
    double machiningTimeS = 0.0;  // from motion in simulated time (task::MachiningClock)
    Pose workOffset{};            // machine coordinates of the stream's origin (the preset)
};

// The JSON report of `kerf run` (keys documented in docs/headless.md).
nlohmann::json buildRunReport(const RunSummary& summary, const canon::PathStatistics& statistics,
                              const machine::MachineConfig& machine);

nlohmann::json diagnosticsJson(const DiagnosticList& diagnostics);

// The report as text. Program text and file names may hold bytes that are not UTF-8 (a Latin-1
// program, a file name): each invalid sequence becomes U+FFFD, as JSON has to be UTF-8.
std::string reportText(const nlohmann::json& report);

}  // namespace kerf::app
