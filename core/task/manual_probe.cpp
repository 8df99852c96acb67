#include "core/task/manual_probe.h"

#include <string>

#include "core/base/translate.h"
#include "core/program/nc_root.h"
#include "core/tables/probe_table.h"
#include "core/tables/tool_table.h"
#include "core/workpiece/blank_solids.h"
#include "core/workpiece/simulated_part.h"

namespace kerf::task {

namespace {

// Something under that name, a dangling link too: a table that may be missing is read whenever
// this is true, so a link out of the NC root, a FIFO or a folder in its place is an error
// rather than "no table, use the defaults".
bool isThere(const std::filesystem::path& file) {
    std::error_code ignored;
    return std::filesystem::exists(std::filesystem::symlink_status(file, ignored));
}

Diagnostic probingError(std::string messageTemplate, std::vector<std::string> args = {}) {
    Diagnostic d;
    d.severity = Severity::Error;
    d.code = "PRB-012";
    d.messageTemplate = std::move(messageTemplate);
    d.args = std::move(args);
    return d;
}

}  // namespace

Expected<ManualProbe> manualProbe(const std::filesystem::path& ncRoot, int toolNumber) {
    if (toolNumber <= 0)
        return probingError(
            KERF_TR_NOOP("manual probing: call the touch probe with TOOL CALL first (MDI)"));
    const program::NcRoot root(ncRoot);
    const std::filesystem::path toolFile = root.path() / "TOOL.T";
    auto toolBytes = root.read(toolFile);
    if (!toolBytes) return toolBytes.error();
    auto tools = tables::ToolTable::parse(*toolBytes, toolFile.string());
    if (!tools) return tools.error();
    const tables::ToolData* tool = tools->byNumber(toolNumber);
    if (tool == nullptr)
        return probingError(KERF_TR_NOOP("manual probing: tool {1} is not in TOOL.T"),
                            {std::to_string(toolNumber)});
    int row = 1;
    // The table's check made a TP_NO that is not empty a whole number 0-99999.
    if (auto column = tools->table().findColumn("TP_NO")) {
        if (auto number = tools->table().number(tool->row, *column))
            row = static_cast<int>(*number);
    }
    const std::filesystem::path probeFile = root.path() / "tchprobe.tp";
    auto probeBytes =
        isThere(probeFile) ? root.read(probeFile) : tables::ProbeTable::createDefault();
    auto probes = probeBytes ? tables::ProbeTable::parse(*probeBytes, probeFile.string())
                             : probeBytes.error();
    if (!probes) return probes.error();
    const tables::ProbeData* probe = probes->byNumber(row);
    if (probe == nullptr)
        return probingError(KERF_TR_NOOP("manual probing: probe {1} is not in tchprobe.tp"),
                            {std::to_string(row)});
    return ManualProbe{tool->radius + tool->deltaRadius, probe->probingFeed, probe->maxProbingPath};
}

workpiece::SimulatedWorkpiece manualProbingPart(
    const machine::MachineConfig& machine, const canon::StockDefinition& blank,
    std::shared_ptr<const workpiece::RemovedMaterial> removed) {
    workpiece::SimulatedWorkpiece part =
        workpiece::simulatedPart(&machine, workpiece::blankSolids(blank), Vec3::Zero());
    part.setRemoved(std::move(removed));
    return part;
}

}  // namespace kerf::task
