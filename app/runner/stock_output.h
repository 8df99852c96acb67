#pragma once

#include <memory>

#include <nlohmann/json.hpp>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/canon/commands.h"

namespace kerf::graphics {
class StockSimulation;
}

namespace kerf::app {

struct Session;

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
