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

// `p` split into its coordinate along the cylinder's axis and the other two (Cylinder's order).
struct AxialSplit {
    double along;
    Vec2 across;
};

AxialSplit splitAlong(Axis axis, const Vec3& p) {
    switch (axis) {
        case Axis::X:
            return {p.x(), Vec2(p.y(), p.z())};
        case Axis::Y:
            return {p.y(), Vec2(p.x(), p.z())};
        default:
            return {p.z(), Vec2(p.x(), p.y())};
    }
}

double cylinderDistance(const Cylinder& c, const Vec3& p) {
    const AxialSplit s = splitAlong(c.axis, p);
    const double radial = (s.across - c.centre).norm() - c.radius;
    const double axial = std::max(c.axialMin - s.along, s.along - c.axialMax);
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

double solidTop(const Solid& solid) {
    if (const auto* box = std::get_if<Box>(&solid.shape)) return box->max.z();
    if (const auto* sphere = std::get_if<Sphere>(&solid.shape))
        return sphere->centre.z() + sphere->radius;
    const auto& cylinder = std::get<Cylinder>(solid.shape);
    // A lying cylinder's centre has z second (y z, x z).
    if (cylinder.axis != Axis::Z) return cylinder.centre.y() + cylinder.radius;
    return cylinder.axialMax;
}

}  // namespace

SimulatedWorkpiece::SimulatedWorkpiece(Placement placement)
    : m_placement(placement),
      m_cosBack(std::cos(placement.rotationDeg * std::numbers::pi / 180.0)),
      m_sinBack(-std::sin(placement.rotationDeg * std::numbers::pi / 180.0)) {}

void SimulatedWorkpiece::add(const Solid& solid) {
    m_solids.push_back(solid);
    // The rotation is about the tool axis: it leaves z alone.
    if (solid.material) {
        const double top = solidTop(solid) + m_placement.origin.z() + m_placement.shift.z();
        m_materialTop = std::max(m_materialTop, top);
    }
}

double SimulatedWorkpiece::blankDistance(const Vec3& real) const {
    // Back into the programmed position: undo the shift, then the rotation.
    const Vec3 d = real - m_placement.origin - m_placement.shift;
    const Vec3 p(d.x() * m_cosBack - d.y() * m_sinBack, d.x() * m_sinBack + d.y() * m_cosBack,
                 d.z());
    double material = std::numeric_limits<double>::infinity();
    double cavity = std::numeric_limits<double>::infinity();
    for (const Solid& solid : m_solids) {
        double& target = solid.material ? material : cavity;
        target = std::min(target, solidDistance(solid, p));
    }
    return std::max(material, -cavity);
}

double SimulatedWorkpiece::distance(const Vec3& real) const {
    const double blank = blankDistance(real);
    if (!m_removed) return blank;
    return std::max(blank, m_removed->depth(real));
}

bool SimulatedWorkpiece::nearestMaterialFound(const Vec3& centre, double radius) const {
    const double d = distance(centre);
    if (d <= 0.0) return true;
    // The bound's gradient points away from the nearest material; step just past it.
    constexpr double kStep = 1e-6;
    Vec3 gradient;
    for (int i = 0; i < 3; ++i) {
        Vec3 e = Vec3::Zero();
        e[i] = kStep;
        gradient[i] = (distance(centre + e) - distance(centre - e)) / (2.0 * kStep);
    }
    if (gradient.norm() < 0.5) return false;
    const Vec3 beyond = centre - (d + 1e-7) * gradient.normalized();
    return (beyond - centre).norm() <= radius + 1e-6 && distance(beyond) <= 0.0;
}

bool SimulatedWorkpiece::provenFree(const Vec3& a, const Vec3& b, double radius) const {
    constexpr int kCellBudget = 200000;
    int cells = 0;
    const Vec3 path = b - a;
    const double length2 = path.squaredNorm();
    auto fromPath = [&](const Vec3& p) {
        const double t = length2 > 0.0 ? std::clamp((p - a).dot(path) / length2, 0.0, 1.0) : 0.0;
        return (p - (a + t * path)).norm();
    };
    // A cube of half-size `half` about `cell`: free unless it may hold material within `radius`
    // of the path.
    auto cellFree = [&](auto& self, const Vec3& cell, double half) -> bool {
        if (++cells > kCellBudget) return false;
        const double reach = half * std::sqrt(3.0);
        const double off = fromPath(cell);
        if (off > radius + reach) return true;  // beside the path
        // The bound is a lower bound of the true distance: no material within it.
        const double d = distance(cell);
        if (d >= reach) return true;
        if (d <= 0.0 && off <= radius) return false;  // material on the path
        if (half < kCoverageResolution) return false;
        const double h = half / 2.0;
        for (int i = 0; i < 8; ++i) {
            const Vec3 offset((i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h);
            if (!self(self, cell + offset, h)) return false;
        }
        return true;
    };
    return cellFree(cellFree, (a + b) / 2.0, std::sqrt(length2) / 2.0 + radius);
}

double SimulatedWorkpiece::provenClearance(const Vec3& centre, const Vec3& direction, double radius,
                                           double limit) const {
    for (double step = std::min(limit, 4.0 * std::max(radius, 1.0)); step >= kCoverageResolution;
         step /= 2.0) {
        if (provenFree(centre, centre + step * direction, radius)) return step;
    }
    return 0.0;
}

bool SimulatedWorkpiece::touches(const Vec3& centre, double radius) const {
    if (m_solids.empty() || distance(centre) > radius) return false;
    if (!hasCuts()) return true;
    return nearestMaterialFound(centre, radius) || !provenFree(centre, centre, radius);
}

std::optional<Vec3> SimulatedWorkpiece::touch(const Vec3& start, const Vec3& direction,
                                              double maxPath, double radius) const {
    if (m_solids.empty()) return std::nullopt;
    // Sphere tracing: the distance bound never steps through material; a face met square on is
    // reached in one step.
    constexpr double kContact = 1e-9;
    constexpr int kMaxSteps = 100000;
    // [choice] A touch that needs more proofs than this stops where it is (a contact).
    constexpr int kMaxProofs = 1000;
    int proofs = 0;
    double travelled = 0.0;
    for (int step = 0; step < kMaxSteps && travelled <= maxPath; ++step) {
        const Vec3 centre = start + travelled * direction;
        const double gap = distance(centre) - radius;
        if (gap > kContact) {
            travelled += gap;
            continue;
        }
        if (!hasCuts() || nearestMaterialFound(centre, radius + kContact)) return centre;
        // Inside several sweeps the bound is low: move on by what is proven free.
        if (++proofs > kMaxProofs) return centre;
        const double clearance =
            provenClearance(centre, direction, radius, maxPath - travelled + kCoverageResolution);
        if (clearance <= 0.0) return centre;
        travelled += clearance;
    }
    return std::nullopt;
}

}  // namespace kerf::workpiece
