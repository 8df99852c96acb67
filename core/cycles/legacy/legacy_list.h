#pragma once

#include "core/base/translate.h"
#include "core/cycles/cycle_descriptor.h"
#include "core/cycles/cycle_values.h"

// The legacy cycles' descriptors, each defined with its expansion (legacy_cycles.cpp lists
// them), and what their expansions share.
namespace kerf::cycles {

extern const CycleDescriptor kCycle1, kCycle2, kCycle3, kCycle4, kCycle5, kCycle17;
// The modern cycles they run as.
extern const CycleDescriptor kCycle206, kCycle207, kCycle251, kCycle252, kCycle253, kCycle254,
    kCycle256, kCycle257;

namespace legacy {

inline constexpr double kMaxLength = 99999.9999;
// The sub-blocks every legacy cycle starts with, and the feed.
inline constexpr ParameterDescriptor kSetUp{
    .word = "SET UP",
    .description = KERF_TR_NOOP("Set-up clearance: tool tip at the start to surface"),
    .unit = Unit::Millimetre,
    .min = -kMaxLength,
    .max = kMaxLength};
inline constexpr ParameterDescriptor kLegacyDepth{
    .word = "DEPTH",
    .description = KERF_TR_NOOP("Depth from the surface (the sign gives the direction)"),
    .unit = Unit::Millimetre,
    .min = -kMaxLength,
    .max = kMaxLength};
inline constexpr ParameterDescriptor kPeckingDepth{
    .word = "PECKG",
    .description = KERF_TR_NOOP("Plunging depth per infeed"),
    .unit = Unit::Millimetre,
    .min = -kMaxLength,
    .max = kMaxLength};
// The centre of the obsolete Q-parameter cycles 210-215 (as in cycle 254).
inline constexpr ParameterDescriptor kCentreFirstAxis{
    .q = 216,
    .description = KERF_TR_NOOP("Centre in the 1st axis"),
    .unit = Unit::Millimetre,
    .min = -kMaxLength,
    .max = kMaxLength,
    .defaultValue = 50.0};
inline constexpr ParameterDescriptor kCentreSecondAxis{
    .q = 217,
    .description = KERF_TR_NOOP("Centre in the 2nd axis"),
    .unit = Unit::Millimetre,
    .min = -kMaxLength,
    .max = kMaxLength,
    .defaultValue = 50.0};
inline constexpr ParameterDescriptor kFeed{.word = "F",
                                           .description = KERF_TR_NOOP("Feed rate"),
                                           .unit = Unit::FeedPerMinute,
                                           .min = 0.0,
                                           .max = 99999.0};

// Every parameter of `modern` at its default.
CycleValues defaultsOf(const CycleDescriptor& modern);

// A legacy cycle starts where the tool stands, `setUp` above the surface (on the side the
// depth's sign leaves): the modern cycle's Q200 and Q203, and Q204 = 0, so it ends there too.
void setStartLevels(CycleValues& modern, double start, double setUp, double depth);

// Runs the modern cycle; its errors name the legacy cycle the program wrote.
std::optional<CycleError> expandAs(int legacyNumber, const CycleDescriptor& modern,
                                   const CycleValues& values, const CycleContext& context,
                                   CyclePath& path);

}  // namespace legacy
}  // namespace kerf::cycles
