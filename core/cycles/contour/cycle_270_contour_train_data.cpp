// Cycle 270 CONTOUR TRAIN DATA (spec §6): DEF-active, how cycle 25 approaches and leaves its
// path and on which side the tool runs; the interpreter keeps the values.
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/detail/cycle_list.h"

namespace kerf::cycles {

namespace {

using namespace contour;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 390,
     .description = KERF_TR_NOOP("Type of approach/departure (1 arc, 2 tangent line, "
                                 "3 perpendicular)"),
     .min = 1.0,
     .max = 3.0,
     .defaultValue = 1.0,
     .integer = true},
    {.q = 391,
     .description = KERF_TR_NOOP("Radius compensation (0 R0, 1 RL, 2 RR)"),
     .min = 0.0,
     .max = 2.0,
     .defaultValue = 1.0,
     .integer = true},
    {.q = 392,
     .description = KERF_TR_NOOP("Radius of the approach/departure arc"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 3.0},
    {.q = 393,
     .description = KERF_TR_NOOP("Centre angle of the approach/departure arc"),
     .unit = Unit::Degrees,
     .min = 0.0,
     .max = 99999.9999,
     .defaultValue = 45.0},
    {.q = 394,
     .description = KERF_TR_NOOP("Distance of the auxiliary point"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 2.0},
};

}  // namespace

const CycleDescriptor kCycle270{.number = 270,
                                .name = KERF_TR_NOOP("CONTOUR TRAIN DATA"),
                                .activation = Activation::Def,
                                .group = CycleGroup::Contours,
                                .parameters = kParameters};

}  // namespace kerf::cycles
