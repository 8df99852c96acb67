#pragma once

// Private: short lines along the tool's direction where a rotary table tilts it (scene.cpp).

#include <cstddef>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "graphics/toolpath/toolpath_data.h"

namespace kerf::graphics {

// One line of `lengthMm` from the tip up the tool at points of the path where the tool does not
// stand along the workpiece's Z, at most `maxLines` spread evenly over them; null when there are
// none (a 3-axis path, or a machine without rotary tables).
vtkSmartPointer<vtkPolyData> toolAxisLines(const ToolpathData& data, size_t maxLines,
                                           double lengthMm);

}  // namespace kerf::graphics
