#include "core/task/manual_probe.h"

#include <cstdlib>
#include <string>

#include "core/base/translate.h"
#include "core/program/nc_root.h"
#include "core/tables/probe_table.h"
#include "core/tables/tool_table.h"
#include "core/workpiece/blank_solids.h"
#include "core/workpiece/simulated_part.h"

namespace kerf::task {

namespace {

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
    if (auto column = tools->table().findColumn("TP_NO")) {
        const std::string_view cell = tools->table().cell(tool->row, *column);
        if (!cell.empty()) row = std::atoi(std::string(cell).c_str());
    }
    const std::filesystem::path probeFile = root.path() / "tchprobe.tp";
    auto probeBytes = root.read(probeFile);
    auto probes = probeBytes ? tables::ProbeTable::parse(*probeBytes, probeFile.string())
                             : tables::ProbeTable::parse(tables::ProbeTable::createDefault());
    if (!probes) return probes.error();
    const tables::ProbeData* probe = probes->byNumber(row);
    if (probe == nullptr)
        return probingError(KERF_TR_NOOP("manual probing: probe {1} is not in tchprobe.tp"),
                            {std::to_string(row)});
    return ManualProbe{tool->radius + tool->deltaRadius, probe->probingFeed, probe->maxProbingPath};
}

workpiece::SimulatedWorkpiece manualProbingPart(const machine::MachineConfig& machine,
                                                const canon::StockDefinition& blank) {
    return workpiece::simulatedPart(&machine, workpiece::blankSolids(blank), Vec3::Zero());
}

}  // namespace kerf::task
