#pragma once

#include "core/base/translate.h"
#include "core/cycles/cycle_parameter.h"

// Parameters shared by many cycles (spec 1.5), with the ranges of the TNC 320 manual.
namespace kerf::cycles::common {

inline constexpr double kLength = 99999.9999;

// A parameter a later software appended to the cycle (spec 1.4 rule 5): a block written by an
// older control without it runs with the default.
constexpr ParameterDescriptor addedLater(ParameterDescriptor p) {
    p.optional = true;
    return p;
}
inline constexpr double kFeed = 99999.999;

inline constexpr ParameterDescriptor kSetUpClearance{
    .q = 200,
    .description = KERF_TR_NOOP("Set-up clearance: tool tip to workpiece surface"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 2.0,
    .predef = true};
inline constexpr ParameterDescriptor kDepth{
    .q = 201,
    .description = KERF_TR_NOOP("Depth: workpiece surface to bottom (sign = direction)"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = -20.0};
inline constexpr ParameterDescriptor kThreadDepth{
    .q = 201,
    .description = KERF_TR_NOOP("Thread depth: workpiece surface to thread end"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = -20.0};
inline constexpr ParameterDescriptor kPlungingDepth{
    .q = 202,
    .description = KERF_TR_NOOP("Plunging depth per infeed"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 5.0};
inline constexpr ParameterDescriptor kSurface{
    .q = 203,
    .description = KERF_TR_NOOP("Workpiece surface coordinate"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kSecondClearance{
    .q = 204,
    .description = KERF_TR_NOOP("2nd set-up clearance: no collision above this height"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 50.0,
    .predef = true};
inline constexpr ParameterDescriptor kMinPlungingDepth{
    .q = 205,
    .description = KERF_TR_NOOP("Minimum plunging depth when decreasing"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kPlungeFeed{
    .q = 206,
    .description = KERF_TR_NOOP("Feed rate for plunging"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 150.0,
    .keywords = kFeedAuto | kFeedPerRev};
inline constexpr ParameterDescriptor kMillingFeed{
    .q = 207,
    .description = KERF_TR_NOOP("Feed rate for milling"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 500.0,
    .keywords = kFeedAuto};
inline constexpr ParameterDescriptor kRetractFeed{
    .q = 208,
    .description = KERF_TR_NOOP("Retraction feed rate (0: plunging feed)"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 0.0,
    .keywords = kFeedAuto | kFeedMax,
    .predef = true};
inline constexpr ParameterDescriptor kDwellTop{.q = 210,
                                               .description = KERF_TR_NOOP("Dwell time at the top"),
                                               .unit = Unit::Seconds,
                                               .min = 0.0,
                                               .max = 3600.0,
                                               .defaultValue = 0.0,
                                               .predef = true};
inline constexpr ParameterDescriptor kDwellDepth{.q = 211,
                                                 .description = KERF_TR_NOOP("Dwell time at depth"),
                                                 .unit = Unit::Seconds,
                                                 .min = 0.0,
                                                 .max = 3600.0,
                                                 .defaultValue = 0.0,
                                                 .predef = true};
inline constexpr ParameterDescriptor kDecrement{
    .q = 212,
    .description = KERF_TR_NOOP("Decrement of the plunging depth after each infeed"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kPrePositionFeed{
    .q = 253,
    .description = KERF_TR_NOOP("Feed rate for pre-positioning"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 750.0,
    .keywords = kFeedAuto | kFeedMax,
    .predef = true};
inline constexpr ParameterDescriptor kCountersinkFeed{
    .q = 254,
    .description = KERF_TR_NOOP("Feed rate for countersinking"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 150.0,
    .keywords = kFeedAuto | kFeedPerRev};
inline constexpr ParameterDescriptor kChipBreakRetract{
    .q = 256,
    .description = KERF_TR_NOOP("Retraction distance for chip breaking"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 0.2,
    .predef = true};
inline constexpr ParameterDescriptor kChipBreakDepth{
    .q = 257,
    .description = KERF_TR_NOOP("Depth for chip breaking (0: none)"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kUpperAdvancedStop{
    .q = 258,
    .description = KERF_TR_NOOP("Upper advanced stop distance"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.2};
inline constexpr ParameterDescriptor kSpindleAngle{
    .q = 336,
    .description = KERF_TR_NOOP("Angle for spindle orientation"),
    .unit = Unit::Degrees,
    .min = -360.0,
    .max = 360.0,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kDisengageDirection{
    .q = 214,
    .description = KERF_TR_NOOP("Disengaging direction (0 none, 1 -main, 2 -secondary, 3 +main, "
                                "4 +secondary axis)"),
    .unit = Unit::None,
    .min = 0.0,
    .max = 4.0,
    .defaultValue = 0.0,
    .integer = true};
inline constexpr ParameterDescriptor kNominalDiameter{
    .q = 335,
    .description = KERF_TR_NOOP("Nominal diameter"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 10.0};
inline constexpr ParameterDescriptor kThreadPitch{
    .q = 239,
    .description = KERF_TR_NOOP("Thread pitch (+ right-hand, - left-hand)"),
    .unit = Unit::Millimetre,
    .min = -99.9999,
    .max = 99.9999,
    .defaultValue = 1.0};
inline constexpr ParameterDescriptor kClimbOrUpCut{
    .q = 351,
    .description = KERF_TR_NOOP("Climb (+1) or up-cut (-1) milling with M3"),
    .unit = Unit::None,
    .min = -1.0,
    .max = 1.0,
    .defaultValue = 1.0,
    .predef = true,
    .integer = true};
inline constexpr ParameterDescriptor kThreadsPerStep{
    .q = 355,
    .description = KERF_TR_NOOP("Threads per step (0 one 360° helix, 1 continuous)"),
    .unit = Unit::Count,
    .min = 0.0,
    .max = 99999.0,
    .defaultValue = 0.0,
    .integer = true};
inline constexpr ParameterDescriptor kCountersinkDepth{
    .q = 356,
    .description = KERF_TR_NOOP("Countersinking depth: surface to tool tip"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = -20.0};
inline constexpr ParameterDescriptor kHoleDepth{.q = 356,
                                                .description = KERF_TR_NOOP("Total hole depth"),
                                                .unit = Unit::Millimetre,
                                                .min = -kLength,
                                                .max = kLength,
                                                .defaultValue = -20.0};
inline constexpr ParameterDescriptor kSideClearance{
    .q = 357,
    .description = KERF_TR_NOOP("Clearance to side: tool edge to hole wall"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.2};
inline constexpr ParameterDescriptor kFrontDepth{
    .q = 358,
    .description = KERF_TR_NOOP("Depth at front: surface to tool tip"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kFrontOffset{
    .q = 359,
    .description = KERF_TR_NOOP("Countersinking offset at front (tool centre)"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kApproachFeed{
    .q = 512,
    .description = KERF_TR_NOOP("Feed rate for approaching (0: milling feed)"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 0.0,
    .keywords = kFeedAuto,
    .optional = true};
inline constexpr ParameterDescriptor kStartingPoint{
    .q = 379,
    .description = KERF_TR_NOOP("Deepened starting point below the surface"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kDepthReference{
    .q = 395,
    .description = KERF_TR_NOOP("Depth reference (0 tool tip, 1 cylindrical part)"),
    .unit = Unit::None,
    .min = 0.0,
    .max = 1.0,
    .defaultValue = 0.0,
    .optional = true,
    .integer = true};

}  // namespace kerf::cycles::common
