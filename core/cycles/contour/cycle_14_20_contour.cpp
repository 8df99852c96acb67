// Cycle 14 CONTOUR and cycle 20 CONTOUR DATA (spec §6): DEF-active, the interpreter keeps the
// label list and the values for the SL cycles 21-24 that follow.
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/detail/cycle_list.h"

namespace kerf::cycles {

namespace {

using namespace contour;

// "CYCL DEF 14.1 CONTOUR LABEL 1/2/3": the keyword is language-dependent, the numbers count.
constexpr ParameterDescriptor kLabels[] = {
    {.word = "CONTOUR LABEL",
     .description = KERF_TR_NOOP("Label numbers of the contour subprograms (up to 12, "
                                 "separated by /)"),
     .unit = Unit::Text}};

constexpr ParameterDescriptor kContourData[] = {
    kContourDepth,
    {.q = 2,
     .description = KERF_TR_NOOP("Path overlap factor"),
     .unit = Unit::Factor,
     .min = 0.0001,
     .max = 1.9999,
     .defaultValue = 1.0},
    kSideAllowance,
    {.q = 4,
     .description = KERF_TR_NOOP("Finishing allowance for the floor"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    kSurfaceCoordinate,
    {.q = 6,
     .description = KERF_TR_NOOP("Set-up clearance"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 2.0},
    kClearanceHeight,
    {.q = 8,
     .description = KERF_TR_NOOP("Inside corner rounding radius"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0},
    {.q = 9,
     .description = KERF_TR_NOOP("Direction of rotation (+1 climb, -1 up-cut)"),
     .min = -1.0,
     .max = 1.0,
     .defaultValue = 1.0,
     .integer = true},
};

}  // namespace

const CycleDescriptor kCycle14{.number = 14,
                               .name = KERF_TR_NOOP("CONTOUR"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Contours,
                               .oldStyle = true,
                               .parameters = kLabels};
const CycleDescriptor kCycle20{.number = 20,
                               .name = KERF_TR_NOOP("CONTOUR DATA"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Contours,
                               .parameters = kContourData};

}  // namespace kerf::cycles
