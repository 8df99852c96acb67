#include "core/workpiece/blank_solids.h"

namespace kerf::workpiece {

std::vector<Solid> blankSolids(const canon::StockDefinition& stock) {
    if (const auto* box = std::get_if<canon::StockBox>(&stock.shape))
        return {Solid{Box{box->min, box->max}, true}};
    const auto& cylinder = std::get<canon::StockCylinder>(stock.shape);
    if (cylinder.axis != Axis::X && cylinder.axis != Axis::Y && cylinder.axis != Axis::Z) return {};
    // Along the axis it names, through the workpiece origin (docs/klartext.md).
    const double bottom = cylinder.distanceMm - cylinder.lengthMm;
    std::vector<Solid> solids{Solid{
        Cylinder{Vec2(0.0, 0.0), cylinder.radiusMm, bottom, cylinder.distanceMm, cylinder.axis},
        true}};
    if (cylinder.innerRadiusMm > 0.0) {
        // The bore runs through: the cavity reaches past both faces.
        solids.push_back(Solid{Cylinder{Vec2(0.0, 0.0), cylinder.innerRadiusMm, bottom - 1.0,
                                        cylinder.distanceMm + 1.0, cylinder.axis},
                               false});
    }
    return solids;
}

}  // namespace kerf::workpiece
