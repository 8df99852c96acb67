#include "core/cycles/probing/probe_geometry.h"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

namespace kerf::cycles::probing {

std::optional<FittedCircle> fitCircle(std::span<const Vec2> points) {
    if (points.size() < 3) return std::nullopt;
    // x^2 + y^2 + D x + E y + F = 0 in the least-squares sense, about the mean for conditioning.
    Vec2 mean(0.0, 0.0);
    for (const Vec2& p : points)
        mean += p;
    mean /= static_cast<double>(points.size());
    Eigen::MatrixXd a(points.size(), 3);
    Eigen::VectorXd b(points.size());
    double scale = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec2 p = points[i] - mean;
        a.row(static_cast<Eigen::Index>(i)) << p.x(), p.y(), 1.0;
        b(static_cast<Eigen::Index>(i)) = -p.squaredNorm();
        scale = std::max(scale, p.norm());
    }
    if (scale <= 0.0) return std::nullopt;
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const auto& s = svd.singularValues();
    // Collinear points leave the system without a third independent direction.
    if (s(2) <= 1e-9 * s(0) || s(1) <= 1e-6 * scale) return std::nullopt;
    const Eigen::Vector3d x = svd.solve(b);
    const Vec2 centre(-x(0) / 2.0, -x(1) / 2.0);
    const double r2 = centre.squaredNorm() - x(2);
    if (r2 <= 0.0) return std::nullopt;
    return FittedCircle{centre + mean, std::sqrt(r2)};
}

double normalizedDeg(double degrees) {
    double a = std::fmod(degrees, 360.0);
    if (a <= -180.0) a += 360.0;
    if (a > 180.0) a -= 360.0;
    return a;
}

std::optional<double> lineAngleDeg(const Vec2& a, const Vec2& b) {
    const Vec2 u = b - a;
    if (u.norm() < kMinTouchDistanceMm) return std::nullopt;
    return normalizedDeg(std::atan2(u.y(), u.x()) * 180.0 / std::numbers::pi);
}

std::optional<Vec2> intersect(const Vec2& a1, const Vec2& a2, const Vec2& b1, const Vec2& b2) {
    const Vec2 u = a2 - a1;
    const Vec2 v = b2 - b1;
    if (u.norm() < kMinTouchDistanceMm || v.norm() < kMinTouchDistanceMm) return std::nullopt;
    const double den = u.x() * v.y() - u.y() * v.x();
    if (std::fabs(den) < 1e-9 * u.norm() * v.norm()) return std::nullopt;
    const Vec2 w = b1 - a1;
    const double t = (w.x() * v.y() - w.y() * v.x()) / den;
    return a1 + t * u;
}

}  // namespace kerf::cycles::probing
