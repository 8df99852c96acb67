#include "graphics/stock/machine_stock_options.h"

#include <map>

#include "core/interp/fagor/tables/tool_table.h"
#include "core/program/nc_root.h"
#include "core/tables/tool_table.h"

namespace kerf::graphics {

std::function<MillCutter(const canon::ToolChange&)> millCutterWithPointAngles(
    const tables::ToolTable* tools) {
    std::map<int, double> pointAngles;
    if (tools != nullptr) {
        for (const tables::ToolData& row : tools->tools()) {
            if (row.index == 0) pointAngles[row.number] = row.pointAngle;
        }
    }
    return [pointAngles](const canon::ToolChange& tool) {
        const auto it = pointAngles.find(tool.number);
        return MillCutter::fromGeometry(tool.geometry.radiusMm, tool.geometry.radius2Mm,
                                        it != pointAngles.end() ? it->second : 0.0);
    };
}

std::function<LatheInsert(const canon::ToolChange&)> latheInsertWithPointAngles(
    const fagor::ToolTable* tools) {
    std::optional<fagor::ToolTable> table;
    if (tools != nullptr) table = *tools;
    return [table](const canon::ToolChange& tool) {
        LatheInsert insert = LatheInsert::fromGeometry(tool.geometry);
        const double angle = table ? table->get(tool.number).noseAngle : 0.0;
        if (insert.kind == LatheToolKind::Drill && angle > 0.0 && angle < 180.0) {
            insert.pointAngleDeg = angle;
        }
        return insert;
    };
}

StockOptions stockOptionsFor(const machine::MachineConfig& machine, const tables::ToolTable* tools,
                             std::optional<machine::WorkpieceFrame> workpieceFrame,
                             const std::filesystem::path& ncRoot) {
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
    if (lathe) {
        // The table the FAGOR interpreter reads (docs/fagor.md, "Tables"); unreadable: no
        // NOSEA, the interpreter reports the table.
        std::optional<fagor::ToolTable> latheTools;
        if (!ncRoot.empty()) {
            const program::NcRoot root(ncRoot);
            if (auto bytes = root.read(ncRoot / "fagor_tools.tab")) {
                if (auto parsed = fagor::ToolTable::parse(*bytes)) latheTools = std::move(*parsed);
            }
        }
        options.latheInsert = latheInsertWithPointAngles(latheTools ? &*latheTools : nullptr);
    }
    options.millCutter = millCutterWithPointAngles(tools);
    return options;
}

}  // namespace kerf::graphics
