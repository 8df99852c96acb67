#include "graphics/scene/detail/tool_axis_lines.h"

#include <vector>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

namespace kerf::graphics {

vtkSmartPointer<vtkPolyData> toolAxisLines(const ToolpathData& data, size_t maxLines,
                                           double lengthMm) {
    if (data.toolAxis.empty() || maxLines == 0) return nullptr;
    constexpr double kVertical = 1.0 - 1e-9;
    // Feed moves at each point (a simultaneous move shows how the tool turns), rapids (a table's
    // turn among them) at their end only.
    std::vector<size_t> tilted;
    auto add = [&](size_t i) {
        if (data.toolAxisAt(i).z() < kVertical) tilted.push_back(i);
    };
    for (size_t m = 0; m < data.moveCount(); ++m) {
        const auto [begin, end] = data.pointsOfMove(m);
        if (begin >= end) continue;
        if (data.kinds[m] == MoveKind::Rapid) {
            add(end - 1);
        } else {
            for (size_t i = begin; i < end; ++i)
                add(i);
        }
    }
    if (tilted.empty()) return nullptr;
    const size_t stride = (tilted.size() + maxLines - 1) / maxLines;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    for (size_t k = 0; k < tilted.size(); k += stride) {
        const Vec3 tip = data.point(tilted[k]);
        const Vec3 end = tip + lengthMm * data.toolAxisAt(tilted[k]);
        const vtkIdType ids[2] = {points->InsertNextPoint(tip.data()),
                                  points->InsertNextPoint(end.data())};
        lines->InsertNextCell(2, ids);
    }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetLines(lines);
    return polyData;
}

}  // namespace kerf::graphics
