#pragma once

#include <array>
#include <optional>

#include "core/base/translate.h"
#include "core/cycles/cycle_parameter.h"
#include "core/cycles/probing/probing_cycle.h"

// The old touch-probe cycles written in sub-blocks, one touch each (spec 4 and 5): 0 REF.
// PLANE, 1 POLAR DATUM PLANE, 3 MEASURING, 4 MEASURING IN 3-D. Positions are ball centres in
// the cycles' local frame, as for the 4xx cycles.
namespace kerf::cycles::probing {

struct SingleTouch {
    // 0 and 1: the ball centre first goes there in one rapid move (no positioning logic); an
    // axis without a value keeps its coordinate. 3 and 4 start where the probe stands.
    std::array<std::optional<double>, 3> prePosition;
    Vec3 direction{0.0, 0.0, -1.0};  // unit
    std::optional<double> maxPath;   // 3 and 4: their own; 0 and 1: DIST of the probe table
    // 3 and 4: after the touch the probe stays and retracts by MB against the probing
    // direction, never beyond its start; 0 and 1 return to the start of the touch.
    std::optional<double> retract;
    // 0, 1 and 3 with ERRORMODE 0: a deflected stylus or (0, 1) a miss are errors. 3 and 4
    // report both in their status instead (ERRORMODE 1 for the deflected stylus of 3).
    bool deflectedIsError = true;
    bool missIsError = true;
};

struct SingleTouchResult {
    bool valid = false;        // false: no touch (3, 4: status -1)
    Vec3 ball{0.0, 0.0, 0.0};  // the ball centre as the control computes it, CAL_OF included
    // The same without the centre offset (the spindle axis at the ball's height): what 0, 1
    // and 3 report (spec 1.5, 4: "uncorrected").
    Vec3 uncorrectedBall{0.0, 0.0, 0.0};
};

std::optional<CycleError> runSingleTouch(int cycle, const SingleTouch& touch,
                                         const ProbeData& probe, ProbingMachine& machine,
                                         SingleTouchResult& result);

// The inputs of those sub-blocks, checked like cycle parameters (spec 4 and 5).
namespace single_touch_words {
inline constexpr ParameterDescriptor kResult{.word = "Q",
                                             .description = KERF_TR_NOOP("Result parameter"),
                                             .min = 0.0,
                                             .max = 1999.0,
                                             .integer = true};
inline constexpr ParameterDescriptor kAngle{.word = "ANGLE",
                                            .description = KERF_TR_NOOP("Probing angle"),
                                            .unit = Unit::Degrees,
                                            .min = -180.0,
                                            .max = 180.0};
inline constexpr ParameterDescriptor kPath{.word = "DIST",
                                           .description = KERF_TR_NOOP("Maximum measuring path"),
                                           .unit = Unit::Millimetre,
                                           .min = -99999.9999,
                                           .max = 99999.9999};
inline constexpr ParameterDescriptor kFeed{.word = "F",
                                           .description = KERF_TR_NOOP("Measuring feed"),
                                           .unit = Unit::FeedPerMinute,
                                           .min = 0.0,
                                           .max = 3000.0};
inline constexpr ParameterDescriptor kRetract{
    .word = "MB",
    .description = KERF_TR_NOOP("Maximum retraction path"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = 99999.9999};
inline constexpr ParameterDescriptor kReferenceSystem{
    .word = "REFERENCE SYSTEM",
    .description = KERF_TR_NOOP("Reference system: 0 active, 1 machine"),
    .min = 0.0,
    .max = 1.0,
    .integer = true};
inline constexpr ParameterDescriptor kErrorMode{
    .word = "ERRORMODE",
    .description = KERF_TR_NOOP("Error mode: 0 error if deflected at the start, 1 status -1"),
    .min = 0.0,
    .max = 1.0,
    .integer = true};
}  // namespace single_touch_words

// 0, 1, 3 and 4: the cycles written in sub-blocks that make one touch.
bool isSingleTouchCycle(int number);

// Cycles 1 and 3: `angleDeg` from the probing axis (0 X, 1 Y, 2 Z) towards the next axis of its
// plane (X to Y, Y to Z, Z to X).
Vec3 polarDirection(int axis, double angleDeg);

}  // namespace kerf::cycles::probing
