#pragma once

#include <array>

#include <Eigen/Core>

// The spatial angles SPA, SPB, SPC of PLANE SPATIAL and cycle 19: turns about the machine's X,
// then Y, then Z, so the tilted axes are R = Rz(SPC) Ry(SPB) Rx(SPA). Pure functions.
namespace kerf::klartext {

Eigen::Matrix3d spatialRotation(double spaDeg, double spbDeg, double spcDeg);
// The angles of a tilt R back (degrees); SPA 0 where SPB is +-90 and only SPC - SPA or SPC + SPA
// is defined.
std::array<double, 3> spatialAnglesOf(const Eigen::Matrix3d& rotation);

}  // namespace kerf::klartext
