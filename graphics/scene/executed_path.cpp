#include "graphics/scene/detail/executed_path.h"

#include <algorithm>

#include <vtkProperty.h>

namespace kerf::graphics {

ExecutedPath::ExecutedPath() {
    m_points->SetDataTypeToFloat();
    m_polyData->SetPoints(m_points);
    m_polyData->SetLines(m_lines);
    m_mapper->SetInputData(m_polyData);
    m_mapper->ScalarVisibilityOff();
    // Drawn over the path it covers, and over the highlight of the block being executed (the
    // editor's cursor follows it), which then shows the rest of that block.
    m_mapper->SetResolveCoincidentTopologyToPolygonOffset();
    m_mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -30.0);
    m_actor->SetMapper(m_mapper);
    // Orange, as wide as the highlight: no move kind has this colour.
    m_actor->GetProperty()->SetColor(1.0, 0.50, 0.10);
    m_actor->GetProperty()->SetLineWidth(4.0f);
    m_actor->GetProperty()->LightingOff();
    m_actor->PickableOff();
    m_actor->VisibilityOff();
}

void ExecutedPath::clear() {
    m_points->Reset();
    m_lines->Reset();
    m_points->Modified();
    m_lines->Modified();
    m_polyData->Modified();
    m_from = m_to = m_count = 0;
    m_actor->VisibilityOff();
}

void ExecutedPath::appendPoint(const Vec3& p) {
    const vtkIdType id = m_points->InsertNextPoint(p.x(), p.y(), p.z());
    ++m_count;
    if (id > 0) {
        const vtkIdType ids[2] = {id - 1, id};
        m_lines->InsertNextCell(2, ids);
    }
}

void ExecutedPath::show(const ToolpathData& data, size_t from, size_t to, const Vec3& tip) {
    to = std::min(to, data.pointCount());
    if (from >= to || !tip.allFinite()) return clear();
    // Another start or a step back (a new run): start again.
    const bool restart = m_count == 0 || from != m_from || to < m_to;
    if (restart) {
        clear();
        m_from = from;
        m_to = from;
    }
    // The tip's slot takes the first point written (the segment into it is there already).
    bool intoTipSlot = !restart;
    auto put = [&](const Vec3& p) {
        if (intoTipSlot) {
            m_points->SetPoint(static_cast<vtkIdType>(m_count - 1), p.x(), p.y(), p.z());
            intoTipSlot = false;
        } else {
            appendPoint(p);
        }
    };
    for (size_t i = m_to; i < to; ++i)
        put(data.point(i));
    m_to = to;
    put(tip);
    m_points->Modified();
    m_lines->Modified();
    m_polyData->Modified();
    m_actor->VisibilityOn();
}

}  // namespace kerf::graphics
