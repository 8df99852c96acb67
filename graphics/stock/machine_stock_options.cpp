#include "graphics/stock/machine_stock_options.h"

#include <map>
#include <set>

#include "core/tables/tool_table.h"

namespace kerf::graphics {

std::function<MillCutter(const canon::ToolChange&)> millCutterFromToolTable(
    const tables::ToolTable* tools) {
    std::map<int, double> pointAngles;
    std::set<int> probes;
    if (tools != nullptr) {
        const auto probeNumber = tools->table().findColumn("TP_NO");
        for (const tables::ToolData& row : tools->tools()) {
            if (row.index != 0) continue;
            pointAngles[row.number] = row.pointAngle;
            if (probeNumber && tools->table().number(row.row, *probeNumber)) {
                probes.insert(row.number);
            }
        }
    }
    return [pointAngles, probes](const canon::ToolChange& tool) {
        if (probes.contains(tool.number)) {
            return MillCutter::touchProbeStylus(tool.geometry.radiusMm);
        }
        const auto it = pointAngles.find(tool.number);
        return MillCutter::fromGeometry(tool.geometry.radiusMm, tool.geometry.radius2Mm,
                                        it != pointAngles.end() ? it->second : 0.0);
    };
}

StockOptions stockOptionsFor(const machine::MachineConfig& machine, const tables::ToolTable* tools,
                             std::optional<machine::WorkpieceFrame> workpieceFrame) {
    StockOptions options;
    options.workpieceFrame = std::move(workpieceFrame);
    const bool lathe = machine.kind == machine::MachineKind::Lathe;
    options.machine = lathe ? StockMachine::Lathe : StockMachine::Mill;
    options.deriveStockFromPath = true;
    const machine::BarConfig& bar = machine.bar;
    if (lathe && bar.diameterMm > 0.0) {
        LatheBar blank;
        blank.radiusMm = bar.diameterMm / 2.0;
        blank.innerRadiusMm = bar.boreDiameterMm / 2.0;
        blank.zMax = bar.faceZMm;
        blank.zMin = bar.faceZMm - bar.lengthMm;
        options.bar = blank;
    }
    options.millCutter = millCutterFromToolTable(tools);
    return options;
}

}  // namespace kerf::graphics
