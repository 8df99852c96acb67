#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/canon/commands.h"

namespace kerf::app {

struct Session;

// Parses --size WIDTHxHEIGHT (each 16..8192); nothing if malformed.
std::optional<std::pair<int, int>> parsePictureSize(const std::string& text);

// `kerf run --png/--stock`: collects the toolpath and simulates the stock from the same canonical
// stream the run consumes, then renders the picture (starting Xvfb when there is no display) and
// adds the stock figures to the report.
class PictureOutput {
public:
    PictureOutput(const RunOptions& options, const Session& session);
    ~PictureOutput();
    PictureOutput(const PictureOutput&) = delete;
    PictureOutput& operator=(const PictureOutput&) = delete;

    bool active() const { return m_sink != nullptr; }
    canon::Sink& sink() { return *m_sink; }
    void setStart(const Pose& start);
    // After the run: finishes the stock and writes the picture when the program ran; problems
    // are appended.
    void finish(bool programRan, DiagnosticList& problems);
    // Adds "stock" (with --stock) and "picture" (with --png) to the report.
    void addToReport(nlohmann::json& report) const;

private:
    struct State;
    std::unique_ptr<State> m_state;
    canon::Sink* m_sink = nullptr;
};

}  // namespace kerf::app
