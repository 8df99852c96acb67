#include "core/interp/klartext/cutter_oversize.h"

namespace kerf::klartext {

Vec3 cutterOversizeOffset(const Vec3& normal, const Vec3& tool, double dr, double dr2) {
    // Towards the side of the tool that touches: the normal's part across the tool axis. A normal
    // along the tool touches with the face (or the ball's pole): no sideways part.
    const Vec3 across = normal - normal.dot(tool) * tool;
    const Vec3 side = across.norm() > 1e-9 ? Vec3(across.normalized()) : Vec3(Vec3::Zero());
    return dr2 * (normal - tool) + (dr - dr2) * side;
}

}  // namespace kerf::klartext
