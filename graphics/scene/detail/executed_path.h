#pragma once

// Private: the executed part of the toolpath as one overlay line (scene.cpp).

#include <cstddef>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>

#include "graphics/toolpath/toolpath_data.h"

namespace kerf::graphics {

// Points [from, to) of the toolpath and then the tip, drawn over the path in one colour. A run
// that moves on only appends (the tip's slot takes the next path point), so following a long
// program costs each frame only what it added.
class ExecutedPath {
public:
    ExecutedPath();
    vtkActor* actor() { return m_actor; }

    void show(const ToolpathData& data, size_t from, size_t to, const Vec3& tip);
    void clear();
    // Segments drawn (path segments and the one to the tip).
    size_t segments() const { return m_count > 0 ? m_count - 1 : 0; }

private:
    void appendPoint(const Vec3& p);

    vtkNew<vtkPoints> m_points;
    vtkNew<vtkCellArray> m_lines;
    vtkNew<vtkPolyData> m_polyData;
    vtkNew<vtkPolyDataMapper> m_mapper;
    vtkNew<vtkActor> m_actor;
    size_t m_from = 0;
    size_t m_to = 0;     // path points [m_from, m_to) are in, the tip after them
    size_t m_count = 0;  // points in m_points
};

}  // namespace kerf::graphics
