#pragma once

#include <array>
#include <optional>

#include "core/geometry/axes.h"
#include "core/interp/program_status.h"
#include "core/machine/table_kinematics.h"

// What the position display shows as X, Y, Z while a working plane is tilted (cycle 19, PLANE):
// the tool tip in the plane's program coordinates (the TNC's input system), from the machine's
// axes as motion reports them (linear axes relative to the preset, rotary axes in degrees).
// Without TCPM the tables stand at the plane's solved angles and the map is affine; with TCPM
// they turn away from them, and the tip on the part comes from the kinematics at the rotary
// axes' own angles. Pure; any thread.
namespace kerf::task {

using WorkingPlane = interp::ProgramStatus::Transformations::WorkingPlane;

// The tool tip in the tilted plane at the axes `axes`. `kinematics` is the machine's (none: the
// plane's affine map alone).
Vec3 positionInWorkingPlane(const WorkingPlane& plane,
                            const std::optional<machine::TableKinematics>& kinematics,
                            const std::array<double, kAxisCount>& axes);

// A difference of the linear axes (lag, distance to go) with the axes at `at`, turned into the
// tilted plane (no origin).
Vec3 differenceInWorkingPlane(const WorkingPlane& plane,
                              const std::optional<machine::TableKinematics>& kinematics,
                              const Vec3& difference, const std::array<double, kAxisCount>& at);

}  // namespace kerf::task
