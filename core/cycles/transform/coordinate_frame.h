#pragma once

#include <array>

#include "core/geometry/plane.h"

namespace kerf::cycles {

// The coordinate transformations of cycles 7, 8, 10, 11, 26 and 247 (spec §9): maps program
// coordinates to the workpiece coordinates of the preset the run started with (the frame of the
// canonical stream). Applied innermost first:
//   26 axis-specific scaling about its centre, 11 scaling about the datum, 10 rotation in the
//   working plane about the datum, 8 mirroring about the datum, 7 datum shift, 247 preset.
// Scaling acts on linear axes only, rotation on the two axes of its plane. Two more stages turn
// the linear axes in space: the tilted working plane (cycle 19, PLANE) between the datum shift and
// the preset, and, outermost, the turn of the rotary tables that carry the workpiece, so that the
// canonical stream holds the positions of the machine's linear axes (machine minus preset).
class CoordinateFrame {
public:
    Pose toWorkpiece(const Pose& program) const;
    Pose toProgram(const Pose& workpiece) const;
    // The same in two halves, met in the tilted plane's coordinates (after the datum shift,
    // before the tilt): toWorkpiece = tiltedPlaneToWorkpiece(toTiltedPlane(program)). The outer
    // half (tilt, preset, tables, turns) is affine in X, Y, Z.
    Pose toTiltedPlane(const Pose& program) const;
    Pose fromTiltedPlane(const Pose& tilted) const;
    Pose tiltedPlaneToWorkpiece(const Pose& tilted) const;
    Pose workpieceToTiltedPlane(const Pose& workpiece) const;
    // True when an odd number of the plane's axes is mirrored: arcs turn the other way and
    // radius compensation changes side.
    bool flipsOrientation(Plane plane) const;
    // An arc in `plane` stays an arc: no rotation about another axis, equal scales in the plane.
    bool keepsArcs(Plane plane) const;
    // The same for the inner half only (toTiltedPlane).
    bool flipsOrientationInTiltedPlane(Plane plane) const;
    bool keepsArcsInTiltedPlane(Plane plane) const;
    // The tilt and the tables (or a swivel head's frame) keep `plane` a plane of the machine's
    // linear axes: its normal stays along itself. Radius compensation needs it.
    bool keepsPlane(Plane plane) const;
    // Factor lengths in the working plane are scaled by (uniform scaling only).
    double planeScale(Plane plane) const;
    // Kept by every setter: toPathSpace asks for every block.
    bool identity() const { return m_identity; }

    void setShift(Axis axis, double value, bool incremental);
    void setMirror(AxisMask axes) {
        m_mirror = axes;
        m_identity = computeIdentity();
    }
    void setRotation(double degrees, bool incremental, Plane plane);
    void setScale(double factor) {
        m_scale = factor;
        m_identity = computeIdentity();
    }
    void setAxisScale(Axis axis, double factor);
    void setAxisScaleCentre(Axis axis, double centre);
    // Cycle 247: a new preset, given as its offset from the start preset; clears 7, 8, 10, 11, 26.
    void setPreset(const Pose& offset);
    // Cycle 12 at a pattern point: the point is an additional datum shift of the called program,
    // applied before every other transformation (in the coordinates of the calling program).
    void setPointShift(const Pose& shift) {
        m_pointShift = shift;
        m_identity = computeIdentity();
    }
    const Pose& pointShift() const { return m_pointShift; }

    // The tilted working plane: `rotation` takes tilted axes to untilted ones, about the datum
    // active now; the datum shift active now becomes part of the tilt, later shifts act in the
    // tilted system (spec: a shift before cycle 19 shifts the machine-based system).
    void setTilt(const Eigen::Matrix3d& rotation);
    // Back to the untilted plane; a datum shift made in the tilted system is kept, turned back.
    void clearTilt();
    bool tilted() const { return m_tilted; }
    const Eigen::Matrix3d& tilt() const { return m_tilt; }
    // The rotary tables stand turned: linear axes = rotation * workpiece + offset.
    void setTable(const Eigen::Matrix3d& rotation, const Vec3& offset);
    // M94: whole turns taken off a rotary axis's display (program angle = axis angle - turns),
    // outermost of all, kept through every other transformation.
    void addTurns(Axis axis, double degrees) {
        m_turns[axis] += degrees;
        m_identity = computeIdentity();
    }
    const Pose& turns() const { return m_turns; }

    const Pose& shift() const { return m_shift; }
    const Pose& preset() const { return m_preset; }
    AxisMask mirror() const { return m_mirror; }
    double rotationDeg() const { return m_rotationDeg; }
    double scale() const { return m_scale; }
    // Cycle 26 factors (1 for axes it does not scale), applied on top of scale().
    const std::array<double, kAxisCount>& axisScale() const { return m_axisScale; }

private:
    Pose m_shift{};
    AxisMask m_mirror = 0;
    double m_rotationDeg = 0.0;
    Plane m_rotationPlane = Plane::XY;
    double m_scale = 1.0;
    std::array<double, kAxisCount> m_axisScale{1, 1, 1, 1, 1, 1, 1, 1, 1};
    Pose m_axisScaleCentre{};
    Pose m_preset{};
    Pose m_pointShift{};
    Pose m_turns{};
    bool m_tilted = false;
    Eigen::Matrix3d m_tilt = Eigen::Matrix3d::Identity();
    Vec3 m_tiltOrigin = Vec3::Zero();
    bool m_tabled = false;
    Eigen::Matrix3d m_table = Eigen::Matrix3d::Identity();
    Vec3 m_tableOffset = Vec3::Zero();
    bool m_identity = true;
    bool computeIdentity() const;
    // Tilt and table together: how the frame turns the linear axes.
    Eigen::Matrix3d spatialTurn() const { return m_table * m_tilt; }
};

bool isLinearAxis(Axis axis);

}  // namespace kerf::cycles
