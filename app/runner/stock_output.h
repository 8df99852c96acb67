#pragma once

#include <functional>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "graphics/stock/cutter.h"

namespace kerf::graphics {
class StockSimulation;
}

namespace kerf::app {

struct Session;

// The mill cutter of a tool change: R and R2 of the canonical tool, the point angle (T-ANGLE)
// from the session's tool table (the canonical tool change does not carry it).
std::function<graphics::MillCutter(const canon::ToolChange&)> millCutterFor(const Session& session);

// `kerf run --stock`: simulates material removal from the canonical stream the run consumes and
// adds the stock figures to the report. VTK-free: the picture (--png) only draws its mesh.
class StockOutput {
public:
    StockOutput(const RunOptions& options, const Session& session);
    ~StockOutput();
    StockOutput(const StockOutput&) = delete;
    StockOutput& operator=(const StockOutput&) = delete;

    bool active() const { return m_stock != nullptr; }
    canon::Sink& sink();
    void setStart(const Pose& start);
    // After the run: derives the blank if needed; the simulation's notes become warnings.
    void finish(DiagnosticList& problems);
    // Adds "stock" to the report.
    void addToReport(nlohmann::json& report) const;
    // Nothing without --stock.
    const graphics::StockSimulation* simulation() const { return m_stock.get(); }

private:
    std::filesystem::path m_program;
    std::unique_ptr<graphics::StockSimulation> m_stock;
};

}  // namespace kerf::app
