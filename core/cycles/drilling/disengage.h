#pragma once

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_path.h"

namespace kerf::cycles {

// Unit vector of a disengaging direction Q214 (1 -main, 2 -secondary, 3 +main, 4 +secondary) in
// program coordinates. A mirror image must not turn it (spec, cycle 202), so mirrored axes are
// flipped here and the interpreter's mirroring flips them back.
inline Vec2 disengageDirection(int q214, const CycleContext& context) {
    Vec2 d(0.0, 0.0);
    if (q214 == 1) d = {-1.0, 0.0};
    if (q214 == 2) d = {0.0, -1.0};
    if (q214 == 3) d = {1.0, 0.0};
    if (q214 == 4) d = {0.0, 1.0};
    if (context.mirroredMain) d.x() = -d.x();
    if (context.mirroredSecondary) d.y() = -d.y();
    return d;
}

// Switches the spindle back on as it was before a cycle that oriented (stopped) it.
inline void restoreSpindle(CyclePath& path, const CycleContext& context) {
    if (context.spindle != canon::SpindleDirection::Stopped) {
        path.spindle(context.spindle, context.spindleRpm);
    }
}

}  // namespace kerf::cycles
