// Catalogue entries of the special old-style cycles 9, 12, 13 and 32 (spec §10). The
// interpreter executes them: 9 dwells, 12 calls a program like a machining cycle, 13 sets the
// angle M19 orients to, 32 hands its tolerance to the planner.
#include "core/cycles/common_parameters.h"
#include "core/cycles/cycle_descriptor.h"
#include "core/cycles/detail/cycle_list.h"

namespace kerf::cycles {

namespace {

constexpr ParameterDescriptor kDwell[] = {{.word = "DWELL",
                                           .description = KERF_TR_NOOP("Dwell time"),
                                           .unit = Unit::Seconds,
                                           .min = 0.0,
                                           .max = 3600.0}};
constexpr ParameterDescriptor kProgram[] = {
    {.word = "PGM",
     .description = KERF_TR_NOOP("Program to call as a machining cycle"),
     .unit = Unit::Text}};
constexpr ParameterDescriptor kOrientation[] = {
    {.word = "ANGLE",
     .description = KERF_TR_NOOP("Orientation angle of the spindle"),
     .unit = Unit::Degrees,
     .min = 0.0,
     .max = 360.0}};
constexpr ParameterDescriptor kTolerance[] = {
    {.word = "T",
     .description = KERF_TR_NOOP("Tolerance (0: machine default)"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = 10.0},
    {.word = "HSC-MODE",
     .description = KERF_TR_NOOP("Filter: finishing (0) or roughing (1)"),
     .min = 0.0,
     .max = 1.0,
     .integer = true},
    {.word = "TA",
     .description = KERF_TR_NOOP("Tolerance of rotary axes (0: machine default)"),
     .unit = Unit::Degrees,
     .min = 0.0,
     .max = 10.0}};

}  // namespace

const CycleDescriptor kCycle9{.number = 9,
                              .name = KERF_TR_NOOP("DWELL TIME"),
                              .activation = Activation::Def,
                              .group = CycleGroup::Special,
                              .oldStyle = true,
                              .parameters = kDwell};
const CycleDescriptor kCycle12{.number = 12,
                               .name = KERF_TR_NOOP("PGM CALL"),
                               .group = CycleGroup::Special,
                               .oldStyle = true,
                               .parameters = kProgram};
const CycleDescriptor kCycle13{.number = 13,
                               .name = KERF_TR_NOOP("ORIENTED SPINDLE STOP"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Special,
                               .oldStyle = true,
                               .parameters = kOrientation};
const CycleDescriptor kCycle32{.number = 32,
                               .name = KERF_TR_NOOP("TOLERANCE"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Special,
                               .oldStyle = true,
                               .parameters = kTolerance};

}  // namespace kerf::cycles
