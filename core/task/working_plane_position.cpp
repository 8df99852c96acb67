#include "core/task/working_plane_position.h"

namespace kerf::task {

namespace {

Eigen::Matrix3d planeMap(const WorkingPlane& plane) {
    Eigen::Matrix3d m;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            m(row, column) = plane.axesToProgram[static_cast<size_t>(3 * row + column)];
    return m;
}

// The rotary axes' machine angles as the kinematics name them.
machine::RotaryAngles anglesAt(const WorkingPlane& plane,
                               const machine::TableKinematics& kinematics,
                               const std::array<double, kAxisCount>& axes) {
    auto angle = [&](char letter) {
        const size_t rotary =
            static_cast<size_t>(axisIndex(*axisFromLetter(letter)) - axisIndex(Axis::A));
        return axes[static_cast<size_t>(axisIndex(Axis::A)) + rotary] +
               plane.rotaryPresetDeg[rotary];
    };
    machine::RotaryAngles a;
    a.primaryDeg = angle(kinematics.primary());
    if (kinematics.twoAxes()) a.secondaryDeg = angle(kinematics.secondary());
    return a;
}

bool followsTables(const WorkingPlane& plane,
                   const std::optional<machine::TableKinematics>& kinematics) {
    return plane.tipFollowsTables && kinematics.has_value();
}

}  // namespace

Vec3 positionInWorkingPlane(const WorkingPlane& plane,
                            const std::optional<machine::TableKinematics>& kinematics,
                            const std::array<double, kAxisCount>& axes) {
    Vec3 point{axes[0], axes[1], axes[2]};
    if (followsTables(plane, kinematics)) {
        const Vec3 preset{plane.presetInMachineMm[0], plane.presetInMachineMm[1],
                          plane.presetInMachineMm[2]};
        point = kinematics->tipOf(point, anglesAt(plane, *kinematics, axes), preset,
                                  plane.toolLengthMm);
    }
    const Vec3 origin{plane.programAtAxesZeroMm[0], plane.programAtAxesZeroMm[1],
                      plane.programAtAxesZeroMm[2]};
    return planeMap(plane) * point + origin;
}

Vec3 differenceInWorkingPlane(const WorkingPlane& plane,
                              const std::optional<machine::TableKinematics>& kinematics,
                              const Vec3& difference, const std::array<double, kAxisCount>& at) {
    Vec3 onPart = difference;
    // The tables' turn at `at` takes part directions to machine directions; the difference of
    // the axes is one of machine directions.
    if (followsTables(plane, kinematics))
        onPart = kinematics->workpieceToMachine(anglesAt(plane, *kinematics, at)).transpose() *
                 difference;
    return planeMap(plane) * onPart;
}

}  // namespace kerf::task
