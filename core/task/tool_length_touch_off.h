#pragma once

#include <filesystem>

#include "core/base/expected.h"

namespace kerf::task {

// Tool length touch-off on the mill (Manual operation): the tool in the spindle touches a
// surface whose tool-axis coordinate the operator knows (the workpiece top, a gauge block),
// while the display, computed with TOOL.T's L + DL, shows `shownMm` there.
struct ToolLengthTouch {
    int tool = -1;
    double shownMm = 0.0;  // the tool tip's coordinate the display shows at the touch
    double knownMm = 0.0;  // where the surface really is, same coordinates
};

// Makes the display show the known value: L += shown - known in the NC root's TOOL.T (DL, the
// wear, is kept), replaced atomically through the NC-root file layer. The new L, or why it
// could not be written (no tool in the spindle, no table, the tool not in it).
Expected<double> touchOffToolLength(const std::filesystem::path& ncRoot,
                                    const ToolLengthTouch& touch);

}  // namespace kerf::task
