#include "app/runner/run_report.h"

#include <cmath>

namespace kerf::app {

namespace {

// Rounds to 6 decimals and never writes -0, so reports compare cleanly.
double clean(double value) {
    double rounded = std::round(value * 1e6) / 1e6;
    return rounded == 0.0 ? 0.0 : rounded;
}

double displayed(char letter, double value, bool xInDiameter) {
    return (letter == 'X' && xInDiameter) ? value * 2.0 : value;
}

}  // namespace

std::string reportText(const nlohmann::json& report) {
    return report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

nlohmann::json diagnosticsJson(const DiagnosticList& diagnostics) {
    nlohmann::json list = nlohmann::json::array();
    for (const Diagnostic& d : diagnostics) {
        list.push_back({{"severity", std::string(severityName(d.severity))},
                        {"file", d.file},
                        {"line", d.line},
                        {"column", d.column},
                        {"code", d.code},
                        {"message", d.message()}});
    }
    return list;
}

nlohmann::json buildRunReport(const RunSummary& summary, const canon::PathStatistics& statistics,
                              const machine::MachineConfig& machine) {
    nlohmann::json report;
    report["ok"] = summary.ok;
    report["dialect"] = summary.dialect;
    report["diagnostics"] = diagnosticsJson(summary.diagnostics);
    report["blocks_executed"] = summary.blocksExecuted;
    report["moves"] = {
        {"rapid",
         {{"count", statistics.rapidCount()}, {"length_mm", clean(statistics.rapidLengthMm())}}},
        {"feed",
         {{"count", statistics.feedCount()}, {"length_mm", clean(statistics.feedLengthMm())}}}};
    nlohmann::json lower = nlohmann::json::object();
    nlohmann::json upper = nlohmann::json::object();
    nlohmann::json position = nlohmann::json::object();
    nlohmann::json machinePosition = nlohmann::json::object();
    const auto& bounds = statistics.feedBounds();
    for (char letter : machine.enabledAxisLetters()) {
        auto axis = axisFromLetter(letter);
        if (!axis) continue;
        const size_t i = static_cast<size_t>(axisIndex(*axis));
        const std::string key(1, letter);
        position[key] =
            clean(displayed(letter, statistics.position().values[i], summary.xInDiameter));
        // Machine coordinates of the tool tip: every axis as its drive stands (rotary axes in
        // degrees, a lathe's X as a radius).
        machinePosition[key] =
            clean(statistics.position().values[i] + summary.workOffset.values[i]);
        if (!bounds.empty) {
            double a = displayed(letter, bounds.min[i], summary.xInDiameter);
            double b = displayed(letter, bounds.max[i], summary.xInDiameter);
            lower[key] = clean(std::min(a, b));
            upper[key] = clean(std::max(a, b));
        }
    }
    report["feed_bounds"] = {{"min", lower}, {"max", upper}};
    report["final_position"] = position;
    report["final_machine_position"] = machinePosition;
    report["tool_changes"] = statistics.toolChanges();
    report["machining_time_s"] = clean(summary.machiningTimeS);
    return report;
}

}  // namespace kerf::app
