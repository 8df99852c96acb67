#include "app/runner/stock_output.h"

#include <cmath>
#include <string>
#include <utility>

#include "app/runner/session.h"
#include "core/machine/workpiece_frame.h"
#include "graphics/stock/machine_stock_options.h"
#include "graphics/stock/stock_simulation.h"

namespace kerf::app {

namespace {

double rounded(double value) {
    const double r = std::round(value * 1000.0) / 1000.0;
    return r == 0.0 ? 0.0 : r;
}

}  // namespace

StockOutput::StockOutput(const RunOptions& options, const Session& session)
    : m_program(options.program) {
    if (!options.stock) return;
    // A machine with rotary tables: the stock on the part the tables turn.
    graphics::StockOptions stockOptions =
        graphics::stockOptionsFor(session.machine, session.program.tools.get(),
                                  machine::WorkpieceFrame::of(session.machine, session.workOffset));
    m_stock = std::make_unique<graphics::StockSimulation>(std::move(stockOptions));
}

StockOutput::~StockOutput() = default;

canon::Sink& StockOutput::sink() {
    return *m_stock;
}

void StockOutput::setStart(const Pose& start) {
    if (m_stock) m_stock->setStart(start);
}

void StockOutput::finish(DiagnosticList& problems) {
    if (!m_stock) return;
    m_stock->finish();
    for (const std::string& note : m_stock->notes()) {
        problems.push_back(
            Diagnostic::make(Severity::Warning, "picture", m_program.string(), 0, 0, "{1}", note));
    }
}

void StockOutput::addToReport(nlohmann::json& report) const {
    if (!m_stock) return;
    nlohmann::json notes = nlohmann::json::array();
    for (const std::string& note : m_stock->notes())
        notes.push_back(note);
    report["stock"] = {{"removed_volume_mm3", rounded(m_stock->removedVolumeMm3())},
                       {"initial_volume_mm3", rounded(m_stock->initialVolumeMm3())},
                       {"resolution_mm", rounded(m_stock->resolutionMm())},
                       {"source", m_stock->stockSource()},
                       {"moves", m_stock->movesSimulated()},
                       {"rapid_cuts", m_stock->rapidCuts()},
                       {"notes", notes}};
}

}  // namespace kerf::app
