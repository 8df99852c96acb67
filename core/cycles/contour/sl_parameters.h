#pragma once

#include "core/cycles/common_parameters.h"

// Parameters shared by the SL cycles 20-25 and 276 (spec §6), with the ranges of the TNC 320
// manual. Texts already used elsewhere are reused so that they stay translated.
namespace kerf::cycles::contour {

using common::kFeed;
using common::kLength;

inline constexpr uint8_t kFeedWords = kFeedAuto | kFeedPerRev | kFeedPerTooth;

inline constexpr ParameterDescriptor kContourDepth{
    .q = 1,
    .description = KERF_TR_NOOP("Depth: workpiece surface to bottom (sign = direction)"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = -20.0};
inline constexpr ParameterDescriptor kSideAllowance{
    .q = 3,
    .description = KERF_TR_NOOP("Finishing allowance for the side"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kSurfaceCoordinate{
    .q = 5,
    .description = KERF_TR_NOOP("Workpiece surface coordinate"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kClearanceHeight{
    .q = 7,
    .description = KERF_TR_NOOP("Clearance height (absolute)"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = 50.0};
inline constexpr ParameterDescriptor kClimbOrUpCut{
    .q = 15,
    .description = KERF_TR_NOOP("Climb or up-cut (+1 climb, -1 up-cut, 0 alternating)"),
    .min = -1.0,
    .max = 1.0,
    .defaultValue = 1.0,
    .integer = true};
inline constexpr ParameterDescriptor kPlungingDepth{
    .q = 10,
    .description = KERF_TR_NOOP("Plunging depth per infeed"),
    .unit = Unit::Millimetre,
    .min = -kLength,
    .max = kLength,
    .defaultValue = -5.0};
inline constexpr ParameterDescriptor kPlungeFeed{
    .q = 11,
    .description = KERF_TR_NOOP("Feed rate for plunging"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 150.0,
    .keywords = kFeedWords};
inline constexpr ParameterDescriptor kMillingFeed{
    .q = 12,
    .description = KERF_TR_NOOP("Feed rate for milling"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 500.0,
    .keywords = kFeedWords};
inline constexpr ParameterDescriptor kRetractionFeed{
    .q = 208,
    .description = KERF_TR_NOOP("Retraction feed rate (0: milling feed)"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 0.0,
    .keywords = kFeedAuto | kFeedMax};

}  // namespace kerf::cycles::contour
