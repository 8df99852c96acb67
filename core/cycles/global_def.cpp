#include "core/cycles/global_def.h"

#include <algorithm>
#include <array>

#include "core/cycles/common_parameters.h"

namespace kerf::cycles {

namespace {

using namespace common;

// The seed names each group's contents but not their Q numbers except Q345 (spec 1.7): the
// numbers are those of the cycle parameters they stand for.
constexpr ParameterDescriptor kGeneral[] = {kSetUpClearance, kSecondClearance, kPrePositionFeed,
                                            kRetractFeed};
constexpr ParameterDescriptor kDrilling[] = {kChipBreakRetract, kDwellDepth, kDwellTop};
constexpr ParameterDescriptor kPocket[] = {
    {.q = 370,
     .description = KERF_TR_NOOP("Path overlap factor"),
     .unit = Unit::Factor,
     .min = 0.0001,
     .max = 1.9999,
     .defaultValue = 1.0},
    kClimbOrUpCut,
    {.q = 366,
     .description = KERF_TR_NOOP("Plunging strategy (0 vertical, 1 helical, 2 "
                                 "reciprocating)"),
     .min = 0.0,
     .max = 2.0,
     .defaultValue = 1.0,
     .integer = true}};
constexpr ParameterDescriptor kContour[] = {
    {.q = 6,
     .description = KERF_TR_NOOP("Set-up clearance"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 2.0},
    {.q = 7,
     .description = KERF_TR_NOOP("Clearance height (absolute)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 2,
     .description = KERF_TR_NOOP("Path overlap factor"),
     .unit = Unit::Factor,
     .min = 0.0001,
     .max = 1.9999,
     .defaultValue = 1.0},
    {.q = 9,
     .description = KERF_TR_NOOP("Direction of rotation (+1 climb, -1 up-cut)"),
     .min = -1.0,
     .max = 1.0,
     .defaultValue = 1.0,
     .integer = true}};
constexpr ParameterDescriptor kProbing[] = {
    {.q = 320,
     .description = KERF_TR_NOOP("Set-up clearance of the probe"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0},
    {.q = 260,
     .description = KERF_TR_NOOP("Clearance height"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 100.0},
    {.q = 301,
     .description = KERF_TR_NOOP("Move to clearance height between points"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 1.0,
     .integer = true}};
constexpr ParameterDescriptor kPositioning[] = {
    {.q = 345,
     .description = KERF_TR_NOOP("Height between pattern points: 2nd set-up clearance "
                                 "(1) or the position at the start (0)"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 0.0,
     .integer = true}};

constexpr std::array<GlobalDefGroup, 6> kGroups = {{
    {100, KERF_TR_NOOP("GENERAL"), kGeneral},
    {105, KERF_TR_NOOP("DRILLING"), kDrilling},
    {110, KERF_TR_NOOP("POCKET MILLING"), kPocket},
    {111, KERF_TR_NOOP("CONTOUR MILLING"), kContour},
    {120, KERF_TR_NOOP("PROBING"), kProbing},
    {125, KERF_TR_NOOP("POSITIONING"), kPositioning},
}};

}  // namespace

std::span<const GlobalDefGroup> globalDefGroups() {
    return kGroups;
}

const GlobalDefGroup* findGlobalDefGroup(int number) {
    auto it = std::find_if(kGroups.begin(), kGroups.end(),
                           [number](const GlobalDefGroup& g) { return g.number == number; });
    return it == kGroups.end() ? nullptr : &*it;
}

}  // namespace kerf::cycles
