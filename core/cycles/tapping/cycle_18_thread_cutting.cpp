// Cycle 18 THREAD CUTTING (spec §10): from the current position a spindle-synchronised move by
// DEPTH along the tool axis, lead = PITCH. No approach or departure of its own; a running spindle
// is switched off for the cycle and on again after it; the tool stays at the thread end.
#include "core/cycles/common_parameters.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/tapping/tapping_checks.h"

namespace kerf::cycles {

namespace {

using namespace common;

// Old-style: 18.1 DEPTH = -20 is stored as value 1, 18.2 PITCH = +1 as value 2.
constexpr ParameterDescriptor kParameters[] = {
    {.word = "DEPTH",
     .description = KERF_TR_NOOP("Total hole depth from the current position"),
     .unit = Unit::Millimetre,
     .min = -99999.0,
     .max = 99999.0,
     .defaultValue = -20.0},
    {.word = "PITCH",
     .description = KERF_TR_NOOP("Thread pitch (+ right-hand, - left-hand)"),
     .unit = Unit::Millimetre,
     .min = -99.9999,
     .max = 99.9999,
     .defaultValue = 1.0},
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double depth = v.number(1);
    if (depth == 0.0) return std::nullopt;
    const double lead = v.number(2);
    if (lead == 0.0) {
        return CycleError{
            "cycle-parameter", KERF_TR_NOOP("cycle {1}: the thread pitch is 0"), {"18"}};
    }
    if (auto e = checkToolPitch(18, ctx.tool, lead)) return e;
    const bool running = ctx.spindle != canon::SpindleDirection::Stopped;
    if (running) path.spindle(canon::SpindleDirection::Stopped, ctx.spindleRpm);
    path.threadMove(path.position() + Vec3(0.0, 0.0, depth), lead, 0.0);
    if (running) path.spindle(ctx.spindle, ctx.spindleRpm);
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle18{.number = 18,
                               .name = KERF_TR_NOOP("THREAD CUTTING"),
                               .group = CycleGroup::Tapping,
                               .oldStyle = true,
                               .parameters = kParameters,
                               .expand = expand};

}  // namespace kerf::cycles
