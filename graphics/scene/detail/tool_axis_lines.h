#pragma once

// Private: short lines along the tool's direction where a rotary table tilts it (scene.cpp).

#include <cstddef>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "graphics/toolpath/toolpath_data.h"

namespace kerf::graphics {

// One line of `lengthMm` from the tip up the tool where the tool does not stand along the
// workpiece's Z: at every point of a feed move, at the end of a rapid; at most `maxLines` spread
// evenly over them. Null when there are none (a 3-axis path, a machine without rotary tables).
vtkSmartPointer<vtkPolyData> toolAxisLines(const ToolpathData& data, size_t maxLines,
                                           double lengthMm);

}  // namespace kerf::graphics
