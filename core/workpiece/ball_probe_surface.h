#pragma once

#include <Eigen/Geometry>

#include "core/canon/commands.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {

// What a simulated machine's probe input touches during a TNC probing cycle's touch under motion
// (docs/probing.md, "How a cycle runs"): the ball of the stylus on the program's part. The
// interpreter builds it outside the servo cycle, once per touch, from the part it would probe
// geometrically and from where the real ball centre lies for a tool tip, an affine map (the
// stylus's offsets and the tables' turn stand still during a touch). touches() neither
// allocates nor locks.
class BallProbeSurface final : public canon::ProbeSurface {
public:
    // `ballCentre`: tool tip (stream coordinates) -> real ball centre (the part's coordinates)
    // is ballCentre.linear() * tip + ballCentre.translation().
    BallProbeSurface(SimulatedWorkpiece part, const Eigen::Affine3d& ballCentre, double radius)
        : m_part(std::move(part)), m_ballCentre(ballCentre), m_radius(radius) {}

    bool touches(const Vec3& tip) const override {
        return m_part.touches(m_ballCentre * tip, m_radius);
    }

private:
    SimulatedWorkpiece m_part;
    Eigen::Affine3d m_ballCentre;
    double m_radius;
};

}  // namespace kerf::workpiece
