// Cycle 221 CARTESIAN PATTERN (spec §5): a grid machined line by line, back and forth.
#include <cmath>
#include <numbers>

#include "core/cycles/common_parameters.h"
#include "core/cycles/cycle_descriptor.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/pattern/pattern_plan.h"

namespace kerf::cycles {

namespace {

using namespace common;

// The manual gives no ranges for Q225..Q243 and Q224: the standard ones (spec [inferred]).
constexpr ParameterDescriptor kParameters[] = {
    {.q = 225,
     .description = KERF_TR_NOOP("Starting point in the 1st axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    {.q = 226,
     .description = KERF_TR_NOOP("Starting point in the 2nd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 0.0},
    {.q = 237,
     .description = KERF_TR_NOOP("Spacing in the 1st axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 10.0},
    {.q = 238,
     .description = KERF_TR_NOOP("Spacing in the 2nd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 10.0},
    {.q = 242,
     .description = KERF_TR_NOOP("Number of columns"),
     .unit = Unit::Count,
     .min = 1.0,
     .max = 99999.0,
     .defaultValue = 1.0,
     .integer = true},
    {.q = 243,
     .description = KERF_TR_NOOP("Number of lines"),
     .unit = Unit::Count,
     .min = 1.0,
     .max = 99999.0,
     .defaultValue = 1.0,
     .integer = true},
    {.q = 224,
     .description = KERF_TR_NOOP("Angle of rotation about the starting point"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0,
     .defaultValue = 0.0},
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
};

constexpr double kMaxPoints = 100000.0;

std::optional<CycleError> points(const CycleValues& v, PatternPlan& plan) {
    const int columns = v.integer(242);
    const int lines = v.integer(243);
    if (static_cast<double>(columns) * static_cast<double>(lines) > kMaxPoints) {
        return CycleError{
            "cycle-limit", KERF_TR_NOOP("cycle {1}: more than {2} positions"), {"221", "100000"}};
    }
    const Vec2 start(v.number(225), v.number(226));
    const double a = v.number(224) * std::numbers::pi / 180.0;
    const Vec2 along(std::cos(a), std::sin(a));
    const Vec2 across(-std::sin(a), std::cos(a));
    for (int j = 0; j < lines; ++j) {
        for (int k = 0; k < columns; ++k) {
            // Even lines run in +main-axis direction, odd lines back.
            const int i = j % 2 == 0 ? k : columns - 1 - k;
            const Vec2 p = start + v.number(237) * i * along + v.number(238) * j * across;
            plan.points.push_back({p, std::nullopt, 0.0});
        }
    }
    plan.setUpClearance = v.number(200);
    plan.surface = v.number(203);
    plan.secondClearance = v.number(204);
    plan.travelAtSecondClearance = v.integer(301) == 1;
    plan.rotationDeg = v.number(224);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle221{.number = 221,
                                .name = KERF_TR_NOOP("CARTESIAN PATTERN"),
                                .activation = Activation::Def,
                                .group = CycleGroup::Pattern,
                                .parameters = kParameters,
                                .pattern = points};

}  // namespace kerf::cycles
