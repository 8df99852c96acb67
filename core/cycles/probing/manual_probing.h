#pragma once

#include <array>
#include <optional>
#include <span>

#include "core/geometry/axes.h"

// Manual probing (the TNC's probing functions of Manual operation): the operator positions the
// probe near the workpiece, chooses a direction and touches; the control evaluates the touches
// with the probing cycles' geometry (probe_geometry.h). Workpiece coordinates, tool axis Z.
namespace kerf::cycles::probing {

enum class ManualProbingFunction : uint8_t {
    Rotation,  // PROBING ROT: two touches along one edge give its misalignment
    Position,  // PROBING POS: one touch gives the surface coordinate in its axis
    Corner,    // PROBING P: two touches on each of two edges give their intersection
    Circle,    // PROBING CC: four touches on a hole or a stud give its centre and diameter
    Plane,     // PROBING PL: three touches on a face give its spatial angles A and B
};

// How many touches the function needs.
int manualTouchCount(ManualProbingFunction function);

// One touch: the ball centre when the stylus triggered, and the unit probing direction: the
// operator's axis direction turned by the basic rotation that was active (as the TNC probes
// obliquely in Manual operation, spec 1.5).
struct ManualTouch {
    Vec3 ball{0.0, 0.0, 0.0};
    Vec3 direction{1.0, 0.0, 0.0};
    double basicRotationDeg = 0.0;
};

// The direction a manual touch goes: the axis direction the operator chose (X+ ... Z-) turned
// in the plane by the active basic rotation; Z stays.
Vec3 turnedProbingDirection(const Vec3& axisDirection, double basicRotationDeg);

struct ManualProbingResult {
    // The surface point (Position: its axis only; Corner: the intersection; Circle: the centre)
    // in the system the position display shows: turned by the basic rotation the touches were
    // made under (about the origin), as the TNC shows and sets it.
    std::array<std::optional<double>, 3> point;
    // Rotation, Corner (from the first edge): the edge's angle to the axis at right angles to
    // the probing axis (the operator's, not turned), (-90, 90] degrees: the whole misalignment
    // also when the touches were made under a basic rotation.
    std::optional<double> basicRotationDeg;
    std::optional<double> diameter;  // Circle
    // Plane: the spatial angles (R = Ry(B) Rx(A), C = 0) that turn the tool axis onto the face's
    // normal, degrees; the plane z = z0 + a x + b y gives A = atan2(b, sqrt(1 + a^2)),
    // B = -atan(a).
    std::optional<double> planeADeg;
    std::optional<double> planeBDeg;
};

// The result of the function's touches (exactly manualTouchCount of them), or nothing when the
// touches give none (two points on one spot, parallel edges, points on one line).
std::optional<ManualProbingResult> evaluateManualProbing(ManualProbingFunction function,
                                                         std::span<const ManualTouch> touches,
                                                         double ballRadius);

}  // namespace kerf::cycles::probing
