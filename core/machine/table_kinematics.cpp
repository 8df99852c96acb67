#include "core/machine/table_kinematics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace kerf::machine {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// Directions closer than this (in sine of the angle) count as parallel.
constexpr double kParallel = 1e-9;

Vec3 unitOf(char rotaryLetter) {
    switch (rotaryLetter) {
        case 'A':
            return Vec3::UnitX();
        case 'B':
            return Vec3::UnitY();
        default:
            return Vec3::UnitZ();
    }
}

// (-180, 180]
double wrapped(double degrees) {
    double a = std::remainder(degrees, 360.0);
    if (a <= -180.0) a += 360.0;
    return a;
}

// The angle about the unit axis `u` that turns `from` onto `to` (both with the same component
// along u); nothing when either lies along u.
std::optional<double> angleAbout(const Vec3& u, const Vec3& from, const Vec3& to) {
    const Vec3 a = from - u.dot(from) * u;
    const Vec3 b = to - u.dot(to) * u;
    if (a.norm() < kParallel || b.norm() < kParallel) return std::nullopt;
    return std::atan2(u.dot(a.cross(b)), a.dot(b)) * kDegPerRad;
}

}  // namespace

Rotation principalRotation(char rotaryLetter, double degrees) {
    return Eigen::AngleAxisd(degrees / kDegPerRad, unitOf(rotaryLetter)).toRotationMatrix();
}

std::optional<TableKinematics> TableKinematics::of(const MachineConfig& config) {
    const KinematicsConfig& k = config.kinematics;
    if (k.type == KinematicsType::None) return std::nullopt;
    TableKinematics t;
    t.m_kind = k.type;
    t.m_primary = k.primary;
    t.m_secondary = k.secondary;
    t.m_pivot = Vec3(k.pivotXMm, k.pivotYMm, k.pivotZMm);
    t.m_headPivot = Vec3(k.headPivotXMm, k.headPivotYMm, k.headPivotZMm);
    auto limitsOf = [&config](char letter) {
        Limits limits;
        if (const AxisConfig* axis = config.axis(letter)) {
            limits = {axis->minLimit, axis->maxLimit, axis->endless};
        }
        return limits;
    };
    t.m_primaryLimits = limitsOf(k.primary);
    t.m_secondaryLimits = limitsOf(k.secondary);
    return t;
}

Rotation TableKinematics::workpieceToMachine(const RotaryAngles& angles) const {
    switch (m_kind) {
        case KinematicsType::TableTable:
            return principalRotation(m_primary, -angles.primaryDeg) *
                   principalRotation(m_secondary, -angles.secondaryDeg);
        case KinematicsType::HeadTable:
            return principalRotation(m_secondary, -angles.secondaryDeg);
        case KinematicsType::HeadHead:
            return Rotation::Identity();
        default:
            return principalRotation(m_primary, -angles.primaryDeg);
    }
}

Rotation TableKinematics::headTurn(const RotaryAngles& angles) const {
    switch (m_kind) {
        case KinematicsType::HeadTable:
            return principalRotation(m_primary, angles.primaryDeg);
        case KinematicsType::HeadHead:
            return principalRotation(m_secondary, angles.secondaryDeg) *
                   principalRotation(m_primary, angles.primaryDeg);
        default:
            return Rotation::Identity();
    }
}

Rotation TableKinematics::toolFrame(const RotaryAngles& angles) const {
    return workpieceToMachine(angles).transpose() * headTurn(angles);
}

Vec3 TableKinematics::innerTableAxis(const RotaryAngles& angles) const {
    if (m_kind == KinematicsType::TableTable)
        return principalRotation(m_primary, -angles.primaryDeg) * unitOf(m_secondary);
    return unitOf(innerTable());
}

Vec3 TableKinematics::axesOf(const Vec3& workpiece, const RotaryAngles& angles,
                             const Vec3& presetInMachine, double toolLengthMm) const {
    // machine = M (preset + p - pivot) + pivot; the axes count from the preset. A turned head
    // turns the tip about its pivot, which the axes make up for.
    const Rotation m = workpieceToMachine(angles);
    return m * workpiece + (m - Rotation::Identity()) * (presetInMachine - m_pivot) +
           headOffset(angles, toolLengthMm);
}

Vec3 TableKinematics::headOffset(const RotaryAngles& angles, double toolLengthMm) const {
    if (!hasHead()) return Vec3::Zero();
    return (headTurn(angles) - Rotation::Identity()) * (m_headPivot + toolLengthMm * Vec3::UnitZ());
}

Vec3 TableKinematics::tipOf(const Vec3& axes, const RotaryAngles& angles,
                            const Vec3& presetInMachine, double toolLengthMm) const {
    const Vec3 offset = axesOf(Vec3::Zero(), angles, presetInMachine, toolLengthMm);
    return workpieceToMachine(angles).transpose() * (axes - offset);
}

RotarySolutions TableKinematics::solve(const Vec3& direction, double freeSecondaryDeg) const {
    RotarySolutions out;
    const Vec3 t = direction.normalized();
    const Vec3 up = unitOf(m_primary);
    if (!twoAxes()) {
        // t = Rot(up, p) z: reachable when t keeps z's component along the axis.
        if (std::abs(up.dot(t) - up.dot(Vec3::UnitZ())) > 1e-9) return out;
        const double p = angleAbout(up, Vec3::UnitZ(), t).value_or(0.0);
        out.list[0] = {wrapped(p), 0.0};
        out.count = 1;
        return out;
    }
    // t = Rot(us, s) Rot(up, p) z. The component along us does not change under the secondary
    // rotation: us.(z cos p + (up x z) sin p) = us.t, i.e. a cos p + b sin p = c.
    const Vec3 us = unitOf(m_secondary);
    const double a = us.dot(Vec3::UnitZ());
    const double b = us.dot(up.cross(Vec3::UnitZ()));
    const double c = us.dot(t);
    const double r = std::hypot(a, b);
    if (r < kParallel || std::abs(c) > r + 1e-9) return out;
    const double phi = std::atan2(b, a);
    const double delta = std::acos(std::clamp(c / r, -1.0, 1.0));
    const double candidates[2] = {(phi + delta) * kDegPerRad, (phi - delta) * kDegPerRad};
    for (double p : candidates) {
        const Vec3 v = principalRotation(m_primary, p) * Vec3::UnitZ();
        const double s = angleAbout(us, v, t).value_or(freeSecondaryDeg);
        const RotaryAngles solution{wrapped(p), wrapped(s)};
        if (out.count == 1 && std::abs(out.list[0].primaryDeg - solution.primaryDeg) < 1e-9 &&
            std::abs(wrapped(out.list[0].secondaryDeg - solution.secondaryDeg)) < 1e-9) {
            continue;  // delta 0: one solution
        }
        out.list[static_cast<size_t>(out.count++)] = solution;
    }
    return out;
}

double TableKinematics::alignedSecondaryDeg(const Vec3& frameX, double primaryDeg) const {
    if (!twoAxes()) return 0.0;
    const Vec3 from = principalRotation(m_primary, primaryDeg) * Vec3::UnitX();
    return wrapped(angleAbout(unitOf(m_secondary), from, frameX).value_or(0.0));
}

std::optional<double> TableKinematics::placed(double angle, const Limits& limits, double current) {
    // The turn of `angle` nearest to `current`, then the nearest inside the limits.
    const double nearest = current + std::remainder(angle - current, 360.0);
    if (limits.endless) return nearest;
    std::optional<double> best;
    for (int k = -3; k <= 3; ++k) {
        const double candidate = nearest + 360.0 * k;
        if (candidate < limits.min - 1e-9 || candidate > limits.max + 1e-9) continue;
        if (!best || std::abs(candidate - current) < std::abs(*best - current)) best = candidate;
    }
    return best;
}

std::optional<RotaryAngles> TableKinematics::choose(const RotarySolutions& solutions,
                                                    SolutionChoice rule,
                                                    const RotaryAngles& current) const {
    std::optional<RotaryAngles> best;
    double bestPath = 0.0;
    for (int i = 0; i < solutions.count; ++i) {
        const RotaryAngles& s = solutions.list[static_cast<size_t>(i)];
        if (rule == SolutionChoice::PrimaryPositive && s.primaryDeg < -1e-9) continue;
        if (rule == SolutionChoice::PrimaryNegative && s.primaryDeg > 1e-9) continue;
        auto p = placed(s.primaryDeg, m_primaryLimits, current.primaryDeg);
        auto q = twoAxes() ? placed(s.secondaryDeg, m_secondaryLimits, current.secondaryDeg)
                           : std::optional<double>(0.0);
        if (!p || !q) continue;
        const double path = std::abs(*p - current.primaryDeg) + std::abs(*q - current.secondaryDeg);
        if (!best || path < bestPath - 1e-9) {
            best = RotaryAngles{*p, *q};
            bestPath = path;
        }
    }
    return best;
}

}  // namespace kerf::machine
