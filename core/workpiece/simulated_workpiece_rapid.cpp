// Rapid moves that take material: the collision check of SimulatedWorkpiece.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {

namespace {

// The radius of the cutter's cross-section `height` above its tip (the corner rounded by
// cornerRadius).
double sectionRadius(const Cutter& cutter, double height) {
    const double corner = std::clamp(cutter.cornerRadius, 0.0, cutter.radius);
    if (height >= corner) return cutter.radius;
    const double below = corner - height;
    return cutter.radius - corner + std::sqrt(corner * corner - below * below);
}

}  // namespace

bool SimulatedWorkpiece::segmentInMaterial(const Vec3& a, const Vec3& b) const {
    // Bisection on the distance bounds: a piece whose midpoint is farther from the material
    // than half its length is free; a midpoint in material is the answer.
    constexpr double kShortest = 1e-4;
    const Vec3 mid = (a + b) / 2.0;
    const double half = (b - a).norm() / 2.0;
    if (blankDistance(mid) > half) return false;
    if (hasCuts() && m_removed->containsMovingDisc(a, b, 0.0)) return false;
    const double d = distance(mid);
    if (d < 0.0) return true;
    if (d > half || half < kShortest) return false;
    return segmentInMaterial(a, mid) || segmentInMaterial(mid, b);
}

bool SimulatedWorkpiece::faceInMaterial(const Vec3& a, const Vec3& b, double rim) const {
    // The whole face first (far from the blank, or in one cut all the way: free), halving the
    // move while that may still settle it; then its centre and rim points one by one.
    if (std::min(a.z(), b.z()) > m_materialTop) return false;
    const Vec3 mid = (a + b) / 2.0;
    const double half = (b - a).norm() / 2.0;
    if (blankDistance(mid) > half + rim) return false;
    if (hasCuts() && m_removed->containsMovingDisc(a, b, rim)) return false;
    if (half > kCollisionSpacing) return faceInMaterial(a, mid, rim) || faceInMaterial(mid, b, rim);
    if (segmentInMaterial(a, b)) return true;
    if (rim <= 0.0) return false;
    const int points =
        std::max(8, static_cast<int>(std::ceil(2.0 * std::numbers::pi * rim / kCollisionSpacing)));
    // Round the rim by turning one offset step by step: one cosine for all points.
    const double step = 2.0 * std::numbers::pi / points;
    const double c = std::cos(step);
    const double s = std::sin(step);
    Vec3 offset(rim, 0.0, 0.0);
    for (int i = 0; i < points; ++i) {
        if (segmentInMaterial(a + offset, b + offset)) return true;
        offset = Vec3(c * offset.x() - s * offset.y(), s * offset.x() + c * offset.y(), 0.0);
    }
    return false;
}

bool SimulatedWorkpiece::rapidTakesMaterial(const Cutter& cutter, const Vec3& from,
                                            const Vec3& to) const {
    if (m_solids.empty() || cutter.radius <= 0.0) return false;
    const Vec3 lift(0.0, 0.0, kCollisionDepth);
    const double rim = std::max(sectionRadius(cutter, kCollisionDepth) - kCollisionDepth, 0.0);
    return faceInMaterial(from + lift, to + lift, rim);
}

}  // namespace kerf::workpiece
