#pragma once

#include <optional>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_word.h"
#include "core/cycles/transform/coordinate_frame.h"

// The sub-blocks of the old-style transformation cycles applied to the frame (spec §9). Values
// are already in mm; datum-table entries (7.1 #n) are resolved by the interpreter.
namespace kerf::cycles {

// 7.x X+10 Y-5 IZ+2: absolute values replace the axis shift, incremental ones add to it.
std::optional<CycleError> applyDatumShift(CoordinateFrame& frame, const CycleWords& words);
// 8.1 X Y: the listed axes are mirrored (none: mirroring off). The tool axis cannot be mirrored
// (spec): it is left out and `toolAxisIgnored` is set.
std::optional<CycleError> applyMirror(CoordinateFrame& frame, const CycleWords& words,
                                      Axis toolAxis, bool& toolAxisIgnored);
// 10.1 ROT+35 / IROT+45 in the working plane.
std::optional<CycleError> applyRotation(CoordinateFrame& frame, const CycleWords& words,
                                        Plane plane);
// 11.1 SCL 0.75.
std::optional<CycleError> applyScaling(CoordinateFrame& frame, const CycleWords& words);
// 26.1 X 1.4 Y 0.6 CCX+15 CCY+20.
std::optional<CycleError> applyAxisScaling(CoordinateFrame& frame, const CycleWords& words);

// The axis named by a word such as "X" or "IX" (the I marks an incremental value).
std::optional<Axis> wordAxis(const CycleWord& word, bool& incremental);

}  // namespace kerf::cycles
