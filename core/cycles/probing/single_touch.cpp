#include "core/cycles/probing/single_touch.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/base/translate.h"
#include "core/cycles/probing/probe_sequence.h"

namespace kerf::cycles::probing {

bool isSingleTouchCycle(int number) {
    return number == 0 || number == 1 || number == 3 || number == 4;
}

Vec3 polarDirection(int axis, double angleDeg) {
    const double a = angleDeg * std::numbers::pi / 180.0;
    Vec3 d(0.0, 0.0, 0.0);
    d[axis] = std::cos(a);
    d[(axis + 1) % 3] = std::sin(a);
    return d;
}

namespace {

void keep(const std::optional<Vec3>& hit, const ProbingMachine& machine,
          SingleTouchResult& result) {
    result.valid = hit.has_value();
    if (!hit) return;
    result.ball = *hit;
    const Vec2 offset = machine.centreOffsetApplied();
    result.uncorrectedBall = *hit - Vec3(offset.x(), offset.y(), 0.0);
}

}  // namespace

std::optional<CycleError> runSingleTouch(int cycle, const SingleTouch& touch,
                                         const ProbeData& probe, ProbingMachine& machine,
                                         SingleTouchResult& result) {
    const double path = touch.maxPath.value_or(probe.maxPath);
    Vec3 start = machine.ballCentre();
    for (int i = 0; i < 3; ++i) {
        if (touch.prePosition[static_cast<size_t>(i)]) {
            start[i] = *touch.prePosition[static_cast<size_t>(i)];
        }
    }
    machine.moveTo(start);
    if (machine.deflected()) {
        if (touch.deflectedIsError) {
            return probingError(cycle, "PRB-002",
                                KERF_TR_NOOP("cycle {1}: stylus already deflected"));
        }
        return std::nullopt;
    }
    if (!touch.retract) {
        auto hit = machine.touch(touch.direction, path);
        if (!hit && touch.missIsError) {
            return probingError(cycle, "PRB-001",
                                KERF_TR_NOOP("cycle {1}: touch point not reached within the "
                                             "measuring path DIST = {2} mm"),
                                {std::to_string(path)});
        }
        keep(hit, machine, result);
        return std::nullopt;
    }
    auto hit = machine.touchAndStay(touch.direction, path);
    const Vec3 end = hit ? *hit : Vec3(start + path * touch.direction);
    // Back by MB, never beyond the start of the measurement.
    const double back = std::min(*touch.retract, (end - start).norm());
    if (back > 0.0) machine.moveTo(end - back * touch.direction);
    keep(hit, machine, result);
    return std::nullopt;
}

}  // namespace kerf::cycles::probing
