#include "core/cycles/contour/sl_end_position.h"

namespace kerf::cycles::contour {

void finishSlCycle(CyclePath& path, const CycleContext& context, double clearanceW, double up,
                   const Feed& feed) {
    path.moveW(clearanceW, feed);
    if (!context.slReturnToStart) return;
    const Vec3& start = context.start;
    // Never through the workpiece: the plane move at whichever height is farther out.
    if ((start.z() - clearanceW) * up > 0.0) path.rapidW(start.z());
    path.rapidUv({start.x(), start.y()});
    path.rapidW(start.z());
}

}  // namespace kerf::cycles::contour
