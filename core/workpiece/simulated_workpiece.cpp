#include "core/workpiece/simulated_workpiece.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace kerf::workpiece {

namespace {

double boxDistance(const Box& box, const Vec3& p) {
    const Vec3 centre = (box.min + box.max) / 2.0;
    const Vec3 half = (box.max - box.min) / 2.0;
    const Vec3 q = (p - centre).cwiseAbs() - half;
    const double outside = q.cwiseMax(0.0).norm();
    const double inside = std::min(q.maxCoeff(), 0.0);
    return outside + inside;
}

double cylinderDistance(const Cylinder& c, const Vec3& p) {
    const double radial = (Vec2(p.x(), p.y()) - c.centre).norm() - c.radius;
    const double axial = std::max(c.zMin - p.z(), p.z() - c.zMax);
    const Vec2 q(radial, axial);
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

double solidDistance(const Solid& solid, const Vec3& p) {
    if (const auto* box = std::get_if<Box>(&solid.shape)) return boxDistance(*box, p);
    if (const auto* sphere = std::get_if<Sphere>(&solid.shape)) {
        return (p - sphere->centre).norm() - sphere->radius;
    }
    return cylinderDistance(std::get<Cylinder>(solid.shape), p);
}

}  // namespace

double SimulatedWorkpiece::distance(const Vec3& real) const {
    // Back into the programmed position: undo the shift, then the rotation.
    const double a = -m_placement.rotationDeg * std::numbers::pi / 180.0;
    const Vec3 d = real - m_placement.origin - m_placement.shift;
    const Vec3 p(d.x() * std::cos(a) - d.y() * std::sin(a),
                 d.x() * std::sin(a) + d.y() * std::cos(a), d.z());
    double material = std::numeric_limits<double>::infinity();
    double cavity = std::numeric_limits<double>::infinity();
    for (const Solid& solid : m_solids) {
        double& target = solid.material ? material : cavity;
        target = std::min(target, solidDistance(solid, p));
    }
    return std::max(material, -cavity);
}

bool SimulatedWorkpiece::touches(const Vec3& centre, double radius) const {
    return !m_solids.empty() && distance(centre) <= radius;
}

std::optional<Vec3> SimulatedWorkpiece::touch(const Vec3& start, const Vec3& direction,
                                              double maxPath, double radius) const {
    if (m_solids.empty()) return std::nullopt;
    // Sphere tracing: the distance bound never steps through material; a face met square on is
    // reached in one step.
    constexpr double kContact = 1e-9;
    constexpr int kMaxSteps = 100000;
    double travelled = 0.0;
    for (int step = 0; step < kMaxSteps && travelled <= maxPath; ++step) {
        const Vec3 centre = start + travelled * direction;
        const double gap = distance(centre) - radius;
        if (gap <= kContact) return centre;
        travelled += gap;
    }
    return std::nullopt;
}

}  // namespace kerf::workpiece
