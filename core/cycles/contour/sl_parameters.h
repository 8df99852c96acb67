#pragma once

#include "core/cycles/common_parameters.h"

// Parameters shared by the SL cycles 20-24 (spec §6), with the ranges of the TNC 320 manual.
// Texts already used elsewhere are reused so that they stay translated.
namespace kerf::cycles::contour {

using common::kFeed;
using common::kLength;

inline constexpr uint8_t kFeedWords = kFeedAuto | kFeedPerRev | kFeedPerTooth;

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
