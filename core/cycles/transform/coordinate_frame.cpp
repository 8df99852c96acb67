#include "core/cycles/transform/coordinate_frame.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace kerf::cycles {

namespace {

Axis axisAt(int i) {
    return static_cast<Axis>(i);
}

void rotate(Pose& p, Plane plane, double degrees) {
    if (degrees == 0.0) return;
    const PlaneAxes axes = planeAxes(plane);
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    const double u = p[axes.first], v = p[axes.second];
    p[axes.first] = c * u - s * v;
    p[axes.second] = s * u + c * v;
}

}  // namespace

bool isLinearAxis(Axis axis) {
    return axis != Axis::A && axis != Axis::B && axis != Axis::C;
}

Pose CoordinateFrame::toWorkpiece(const Pose& program) const {
    return tiltedPlaneToWorkpiece(toTiltedPlane(program));
}

Pose CoordinateFrame::toProgram(const Pose& workpiece) const {
    return fromTiltedPlane(workpieceToTiltedPlane(workpiece));
}

Pose CoordinateFrame::toTiltedPlane(const Pose& program) const {
    Pose p = program;
    for (size_t k = 0; k < p.values.size(); ++k)
        p.values[k] += m_pointShift.values[k];
    for (int i = 0; i < kAxisCount; ++i) {
        if (!isLinearAxis(axisAt(i))) continue;
        const auto k = static_cast<size_t>(i);
        const double c = m_axisScaleCentre.values[k];
        p.values[k] = (c + m_axisScale[k] * (p.values[k] - c)) * m_scale;
    }
    rotate(p, m_rotationPlane, m_rotationDeg);
    for (int i = 0; i < kAxisCount; ++i) {
        const auto k = static_cast<size_t>(i);
        if ((m_mirror & axisBit(axisAt(i))) != 0) p.values[k] = -p.values[k];
        p.values[k] += m_shift.values[k];
    }
    return p;
}

Pose CoordinateFrame::tiltedPlaneToWorkpiece(const Pose& tilted) const {
    Pose p = tilted;
    if (m_tilted) p.setXyz(m_tiltOrigin + m_tilt * p.xyz());
    for (size_t k = 0; k < p.values.size(); ++k)
        p.values[k] += m_preset.values[k];
    if (m_tabled) p.setXyz(m_table * p.xyz() + m_tableOffset);
    for (size_t k = 0; k < p.values.size(); ++k)
        p.values[k] += m_turns.values[k];
    return p;
}

Pose CoordinateFrame::workpieceToTiltedPlane(const Pose& workpiece) const {
    Pose p = workpiece;
    for (size_t k = 0; k < p.values.size(); ++k)
        p.values[k] -= m_turns.values[k];
    if (m_tabled) p.setXyz(m_table.transpose() * (p.xyz() - m_tableOffset));
    for (size_t k = 0; k < p.values.size(); ++k)
        p.values[k] -= m_preset.values[k];
    if (m_tilted) p.setXyz(m_tilt.transpose() * (p.xyz() - m_tiltOrigin));
    return p;
}

Pose CoordinateFrame::fromTiltedPlane(const Pose& tilted) const {
    Pose p = tilted;
    for (int i = 0; i < kAxisCount; ++i) {
        const auto k = static_cast<size_t>(i);
        p.values[k] -= m_shift.values[k];
        if ((m_mirror & axisBit(axisAt(i))) != 0) p.values[k] = -p.values[k];
    }
    rotate(p, m_rotationPlane, -m_rotationDeg);
    for (int i = 0; i < kAxisCount; ++i) {
        if (!isLinearAxis(axisAt(i))) continue;
        const auto k = static_cast<size_t>(i);
        const double c = m_axisScaleCentre.values[k];
        p.values[k] = c + (p.values[k] / m_scale - c) / m_axisScale[k];
    }
    for (size_t k = 0; k < p.values.size(); ++k)
        p.values[k] -= m_pointShift.values[k];
    return p;
}

namespace {

// The unit normal of a plane (the axis that is not in it).
Vec3 normalOf(Plane plane) {
    const PlaneAxes axes = planeAxes(plane);
    Vec3 first = Vec3::Zero(), second = Vec3::Zero();
    first[axisIndex(axes.first)] = 1.0;
    second[axisIndex(axes.second)] = 1.0;
    return first.cross(second);
}

}  // namespace

bool CoordinateFrame::flipsOrientation(Plane plane) const {
    // A spatial turn that lays the plane upside down reverses its arcs too.
    bool turned = false;
    if (m_tilted || m_tabled) {  // every block asks: the normal only when there is a turn
        const Vec3 n = normalOf(plane);
        turned = (spatialTurn() * n).dot(n) < 0.0;
    }
    return flipsOrientationInTiltedPlane(plane) != turned;
}

bool CoordinateFrame::flipsOrientationInTiltedPlane(Plane plane) const {
    const PlaneAxes axes = planeAxes(plane);
    const bool a = (m_mirror & axisBit(axes.first)) != 0;
    const bool b = (m_mirror & axisBit(axes.second)) != 0;
    return a != b;
}

bool CoordinateFrame::keepsPlane(Plane plane) const {
    if (!m_tilted && !m_tabled) return true;
    const Vec3 n = normalOf(plane);
    return std::abs(std::abs((spatialTurn() * n).dot(n)) - 1.0) <= 1e-9;
}

bool CoordinateFrame::keepsArcs(Plane plane) const {
    return keepsPlane(plane) && keepsArcsInTiltedPlane(plane);
}

bool CoordinateFrame::keepsArcsInTiltedPlane(Plane plane) const {
    if (m_rotationDeg != 0.0 && plane != m_rotationPlane) return false;
    const PlaneAxes axes = planeAxes(plane);
    return m_axisScale[static_cast<size_t>(axes.first)] ==
           m_axisScale[static_cast<size_t>(axes.second)];
}

double CoordinateFrame::planeScale(Plane plane) const {
    return m_scale * m_axisScale[static_cast<size_t>(planeAxes(plane).first)];
}

bool CoordinateFrame::computeIdentity() const {
    if (m_tilted || m_tabled) return false;
    if (m_mirror != 0 || m_rotationDeg != 0.0 || m_scale != 1.0) return false;
    for (size_t k = 0; k < static_cast<size_t>(kAxisCount); ++k) {
        if (m_shift.values[k] != 0.0 || m_preset.values[k] != 0.0 || m_axisScale[k] != 1.0 ||
            m_pointShift.values[k] != 0.0 || m_turns.values[k] != 0.0) {
            return false;
        }
    }
    return true;
}

void CoordinateFrame::setShift(Axis axis, double value, bool incremental) {
    m_shift[axis] = incremental ? m_shift[axis] + value : value;
    m_identity = computeIdentity();
}

void CoordinateFrame::setRotation(double degrees, bool incremental, Plane plane) {
    m_rotationDeg = incremental ? m_rotationDeg + degrees : degrees;
    m_rotationPlane = plane;
    m_identity = computeIdentity();
}

void CoordinateFrame::setAxisScale(Axis axis, double factor) {
    m_axisScale[static_cast<size_t>(axisIndex(axis))] = factor;
    m_identity = computeIdentity();
}

void CoordinateFrame::setAxisScaleCentre(Axis axis, double centre) {
    m_axisScaleCentre[axis] = centre;
}

void CoordinateFrame::setPreset(const Pose& offset) {
    // The point shift belongs to the running program call, the tilt and the tables' turn to the
    // machine: cycle 247 keeps them.
    CoordinateFrame kept = *this;
    *this = CoordinateFrame();
    m_preset = offset;
    m_pointShift = kept.m_pointShift;
    m_turns = kept.m_turns;
    m_tilted = kept.m_tilted;
    m_tilt = kept.m_tilt;
    m_tiltOrigin = kept.m_tiltOrigin;
    m_tabled = kept.m_tabled;
    m_table = kept.m_table;
    m_tableOffset = kept.m_tableOffset;
    m_identity = computeIdentity();
}

void CoordinateFrame::setTilt(const Eigen::Matrix3d& rotation) {
    m_tiltOrigin += m_tilt * m_shift.xyz();
    m_shift.setXyz(Vec3::Zero());
    m_tilt = rotation;
    m_tilted = true;
    m_identity = false;
}

void CoordinateFrame::clearTilt() {
    m_shift.setXyz(m_tiltOrigin + m_tilt * m_shift.xyz());
    m_tiltOrigin = Vec3::Zero();
    m_tilt = Eigen::Matrix3d::Identity();
    m_tilted = false;
    m_identity = computeIdentity();
}

void CoordinateFrame::setTable(const Eigen::Matrix3d& rotation, const Vec3& offset) {
    m_table = rotation;
    m_tableOffset = offset;
    m_tabled = !rotation.isIdentity(1e-12) || !offset.isZero(1e-12);
    m_identity = computeIdentity();
}

}  // namespace kerf::cycles
