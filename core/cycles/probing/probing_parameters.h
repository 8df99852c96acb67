#pragma once

#include "core/base/translate.h"
#include "core/cycles/cycle_parameter.h"

// Parameters shared by the probing cycles: one Q number means the same thing in every cycle
// (spec 1.1 rule 6), with the ranges of the TNC 320 manual.
namespace kerf::cycles::probing::parameters {

inline constexpr double kLength = 99999.9999;

constexpr ParameterDescriptor length(uint16_t q, const char* description, double min = -kLength,
                                     double defaultValue = 0.0) {
    return {.q = q,
            .description = description,
            .unit = Unit::Millimetre,
            .min = min,
            .max = kLength,
            .defaultValue = defaultValue};
}
constexpr ParameterDescriptor choice(uint16_t q, const char* description, double min, double max,
                                     double defaultValue) {
    return {.q = q,
            .description = description,
            .min = min,
            .max = max,
            .defaultValue = defaultValue,
            .integer = true};
}
constexpr ParameterDescriptor angle(uint16_t q, const char* description, double limit) {
    return {.q = q, .description = description, .unit = Unit::Degrees, .min = -limit, .max = limit};
}
constexpr ParameterDescriptor optionalParameter(ParameterDescriptor p) {
    p.optional = true;
    return p;
}

inline constexpr ParameterDescriptor kMeasuringHeight =
    length(261, KERF_TR_NOOP("Measuring height: ball centre in the tool axis"));
inline constexpr ParameterDescriptor kSetUpClearance{
    .q = 320,
    .description = KERF_TR_NOOP("Set-up clearance, added to SET_UP of the probe table"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .predef = true};
inline constexpr ParameterDescriptor kClearanceHeight{
    .q = 260,
    .description = KERF_TR_NOOP("Clearance height: no collision with workpiece or fixtures"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = 20.0,
    .predef = true};
inline constexpr ParameterDescriptor kMoveToClearance{
    .q = 301,
    .description = KERF_TR_NOOP("Move to clearance height between points: 0 no, 1 yes"),
    .min = 0.0,
    .max = 1.0,
    .defaultValue = 1.0,
    .predef = true,
    .integer = true};
inline constexpr ParameterDescriptor kTableRow =
    choice(305, KERF_TR_NOOP("Number in table: 0 sets the display (active preset)"), 0, 99999, 0);
inline constexpr ParameterDescriptor kTransfer =
    choice(303, KERF_TR_NOOP("Measured-value transfer: 0 datum table, 1 preset table"), -1, 1, 1);
inline constexpr ParameterDescriptor kDatumMain =
    length(331, KERF_TR_NOOP("New datum in the main axis"));
inline constexpr ParameterDescriptor kDatumSecondary =
    length(332, KERF_TR_NOOP("New datum in the secondary axis"));
inline constexpr ParameterDescriptor kDatumToolAxis =
    length(333, KERF_TR_NOOP("New datum in the tool axis"));
inline constexpr ParameterDescriptor kProbeToolAxis =
    choice(381, KERF_TR_NOOP("Probe in the tool axis too: 0 no, 1 yes"), 0, 1, 0);
inline constexpr ParameterDescriptor kToolAxisPointMain =
    length(382, KERF_TR_NOOP("Tool-axis touch point, main axis"));
inline constexpr ParameterDescriptor kToolAxisPointSecondary =
    length(383, KERF_TR_NOOP("Tool-axis touch point, secondary axis"));
inline constexpr ParameterDescriptor kToolAxisSurface =
    length(384, KERF_TR_NOOP("Tool-axis touch point, nominal surface in the tool axis"));
inline constexpr ParameterDescriptor kMeasuringAxis =
    choice(272, KERF_TR_NOOP("Measuring axis: 1 main axis, 2 secondary axis"), 1, 2, 1);
inline constexpr ParameterDescriptor kTraverseDirection{
    .q = 267,
    .description = KERF_TR_NOOP("Traverse direction toward the workpiece: -1 or +1"),
    .min = -1.0,
    .max = 1.0,
    .defaultValue = 1.0,
    .integer = true};
inline constexpr ParameterDescriptor kStartAngle =
    angle(325, KERF_TR_NOOP("Starting angle: main axis to touch point 1"), 360.0);
inline constexpr ParameterDescriptor kStepAngle{
    .q = 247,
    .description = KERF_TR_NOOP("Stepping angle between touch points (sign = direction)"),
    .unit = Unit::Degrees,
    .min = -120.0,
    .max = 120.0,
    .defaultValue = 90.0};
inline constexpr ParameterDescriptor kProbePoints =
    choice(423, KERF_TR_NOOP("Number of touch points in the plane: 3 or 4"), 3, 4, 4);
inline constexpr ParameterDescriptor kTraverseType =
    choice(365, KERF_TR_NOOP("Path between points: 0 straight line, 1 arc"), 0, 1, 1);
inline constexpr ParameterDescriptor kMeasuringLog =
    choice(281, KERF_TR_NOOP("Measuring log: 0 none, 1 write TCHPRnnn.TXT, 2 also stop"), 0, 2, 0);
inline constexpr ParameterDescriptor kStopOnToleranceError =
    choice(309, KERF_TR_NOOP("PGM stop on tolerance error: 0 no, 1 yes"), 0, 1, 0);
inline constexpr ParameterDescriptor kMonitoredTool{
    .q = 330,
    .description = KERF_TR_NOOP("Tool for monitoring: 0 none"),
    .min = 0.0,
    .max = 32767.9,
    .toolName = true};

}  // namespace kerf::cycles::probing::parameters
