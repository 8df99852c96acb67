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
class StockOutput;

// Parses --size WIDTHxHEIGHT (each 16..8192); nothing if malformed.
std::optional<std::pair<int, int>> parsePictureSize(const std::string& text);

// `kerf run --png`: collects the toolpath from the canonical stream the run consumes and renders
// the picture (with the stock of --stock). Drawing needs VTK, which `kerf` itself does not load
// (it hands such runs to kerf-gui, app/main.cpp): the implementation is made by
// makePngPicture (app/runner/png_picture.h, library runner_picture).
class PictureOutput {
public:
    virtual ~PictureOutput() = default;
    virtual canon::Sink& sink() = 0;
    virtual void setStart(const Pose& start) = 0;
    // After the run (and after the stock's finish()): writes the picture when the program ran;
    // problems are appended.
    virtual void finish(bool programRan, const StockOutput& stock, DiagnosticList& problems) = 0;
    // Adds "picture" to the report.
    virtual void addToReport(nlohmann::json& report) const = 0;
};

using PictureOutputFactory = std::unique_ptr<PictureOutput> (*)(const RunOptions& options,
                                                                const Session& session);

}  // namespace kerf::app
