// Cycle 220 POLAR PATTERN (spec §5): points on a full or partial circle.
#include <cmath>
#include <numbers>

#include "core/cycles/common_parameters.h"
#include "core/cycles/cycle_descriptor.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pattern/pattern_plan.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr ParameterDescriptor kParameters[] = {
    {.q = 216,
     .description = KERF_TR_NOOP("Centre in the 1st axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 217,
     .description = KERF_TR_NOOP("Centre in the 2nd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 244,
     .description = KERF_TR_NOOP("Pitch circle diameter"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 80.0},
    {.q = 245,
     .description = KERF_TR_NOOP("Starting angle"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 0.0},
    {.q = 246,
     .description = KERF_TR_NOOP("Stopping angle"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 360.0},
    {.q = 247,
     .description = KERF_TR_NOOP("Stepping angle (0: from start, stop and count)"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 0.0},
    {.q = 241,
     .description = KERF_TR_NOOP("Number of operations"),
     .unit = Unit::Count,
     .min = 1.0,
     .max = 99999.0,
     .defaultValue = 8.0,
     .integer = true},
    kSetUpClearance,
    kSurface,
    kSecondClearance,
    {.q = 301,
     .description = KERF_TR_NOOP("Move between operations at set-up clearance (0) or "
                                 "at the 2nd set-up clearance (1)"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 1.0,
     .predef = true,
     .integer = true},
    {.q = 365,
     .description = KERF_TR_NOOP("Type of traverse: straight line (0) or arc on the "
                                 "pitch circle (1)"),
     .min = 0.0,
     .max = 1.0,
     .defaultValue = 0.0,
     .integer = true},
};

std::optional<CycleError> points(const CycleValues& v, PatternPlan& plan) {
    const int count = v.integer(241);
    const double startDeg = v.number(245);
    double stepDeg = v.number(247);
    if (stepDeg == 0.0) {
        const double span = v.number(246) - startDeg;
        if (std::fabs(std::fabs(span) - 360.0) < 1e-9) {
            stepDeg = span / count;
        } else if (count > 1) {
            if (span == 0.0) {
                return CycleError{"cycle-parameter",
                                  KERF_TR_NOOP("cycle {1}: the stopping angle Q246 must differ "
                                               "from the starting angle Q245"),
                                  {"220"}};
            }
            stepDeg = span / (count - 1);
        }
    }
    const Vec2 centre(v.number(216), v.number(217));
    const double radius = v.number(244) / 2.0;
    for (int i = 0; i < count; ++i) {
        const double a = (startDeg + stepDeg * i) * std::numbers::pi / 180.0;
        plan.points.push_back(
            {centre + radius * Vec2(std::cos(a), std::sin(a)), std::nullopt, 0.0});
    }
    plan.setUpClearance = v.number(200);
    plan.surface = v.number(203);
    plan.secondClearance = v.number(204);
    plan.travelAtSecondClearance = v.integer(301) == 1;
    plan.arcTraverse = v.integer(365) == 1;
    plan.arcCentre = centre;
    plan.arcStepRad = stepDeg * std::numbers::pi / 180.0;
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle220{.number = 220,
                                .name = KERF_TR_NOOP("POLAR PATTERN"),
                                .activation = Activation::Def,
                                .group = CycleGroup::Pattern,
                                .parameters = kParameters,
                                .pattern = points};

}  // namespace kerf::cycles
