#pragma once

#include "core/cycles/common_parameters.h"

// Parameters shared by the pocket, stud and slot cycles 251-258 (spec §4), with the ranges of
// the TNC 320 manual. Texts already used elsewhere are reused so that they stay translated.
namespace kerf::cycles::pocket {

using common::kFeed;
using common::kLength;

inline constexpr ParameterDescriptor kOperation{
    .q = 215,
    .description = KERF_TR_NOOP("Machining operation (0 roughing and finishing, 1 roughing, "
                                "2 finishing)"),
    .min = 0.0,
    .max = 2.0,
    .defaultValue = 0.0,
    .integer = true};
inline constexpr ParameterDescriptor kFirstSide{.q = 218,
                                                .description = KERF_TR_NOOP("First side length"),
                                                .unit = Unit::Millimetre,
                                                .min = 0.0,
                                                .max = kLength,
                                                .defaultValue = 80.0};
inline constexpr ParameterDescriptor kSecondSide{.q = 219,
                                                 .description = KERF_TR_NOOP("Second side length"),
                                                 .unit = Unit::Millimetre,
                                                 .min = 0.0,
                                                 .max = kLength,
                                                 .defaultValue = 60.0};
inline constexpr ParameterDescriptor kSideAllowance{
    .q = 368,
    .description = KERF_TR_NOOP("Finishing allowance for the side"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kFloorAllowance{
    .q = 369,
    .description = KERF_TR_NOOP("Finishing allowance for the floor"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kRotation{
    .q = 224,
    .description = KERF_TR_NOOP("Angle of rotation about the starting point"),
    .unit = Unit::Degrees,
    .min = -360.0,
    .max = 360.0,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kPosition{
    .q = 367,
    .description = KERF_TR_NOOP("Position (0 centre, 1 lower left, 2 lower right, 3 upper "
                                "right, 4 upper left corner)"),
    .min = 0.0,
    .max = 4.0,
    .defaultValue = 0.0,
    .integer = true};
inline constexpr ParameterDescriptor kMillingFeed{
    .q = 207,
    .description = KERF_TR_NOOP("Feed rate for milling"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 500.0,
    .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth};
inline constexpr ParameterDescriptor kPlungeFeed{
    .q = 206,
    .description = KERF_TR_NOOP("Feed rate for plunging"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 150.0,
    .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth};
// Studs plunge outside the material and may plunge at rapid.
inline constexpr ParameterDescriptor kStudPlungeFeed{
    .q = 206,
    .description = KERF_TR_NOOP("Feed rate for plunging"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 150.0,
    .keywords = kFeedMax | kFeedAuto | kFeedPerRev | kFeedPerTooth};
inline constexpr ParameterDescriptor kPlungingDepth{
    .q = 202,
    .description = KERF_TR_NOOP("Plunging depth per infeed"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 5.0};
inline constexpr ParameterDescriptor kFinishingInfeed{
    .q = 338,
    .description = KERF_TR_NOOP("Infeed for finishing (0: one infeed)"),
    .unit = Unit::Millimetre,
    .min = 0.0,
    .max = kLength,
    .defaultValue = 0.0};
inline constexpr ParameterDescriptor kOverlap{.q = 370,
                                              .description = KERF_TR_NOOP("Path overlap factor"),
                                              .unit = Unit::Factor,
                                              .min = 0.0001,
                                              .max = 1.9999,
                                              .defaultValue = 1.0,
                                              .predef = true};
inline constexpr ParameterDescriptor kPlunge{
    .q = 366,
    .description = KERF_TR_NOOP("Plunging strategy (0 vertical, 1 helical, 2 "
                                "reciprocating)"),
    .min = 0.0,
    .max = 2.0,
    .defaultValue = 1.0,
    .predef = true,
    .integer = true};
inline constexpr ParameterDescriptor kFinishingFeed{
    .q = 385,
    .description = KERF_TR_NOOP("Feed rate for finishing"),
    .unit = Unit::FeedPerMinute,
    .min = 0.0,
    .max = kFeed,
    .defaultValue = 500.0,
    .keywords = kFeedAuto | kFeedPerRev | kFeedPerTooth};
inline constexpr ParameterDescriptor kFeedReference{
    .q = 439,
    .description = KERF_TR_NOOP("Feed rate reference (0 tool centre, 1 cutting edge when "
                                "side finishing, 2 also floor finishing, 3 always)"),
    .min = 0.0,
    .max = 3.0,
    .defaultValue = 0.0,
    .integer = true};

}  // namespace kerf::cycles::pocket
