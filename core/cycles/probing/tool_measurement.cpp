#include "core/cycles/probing/tool_measurement.h"

#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/cycles/probing/probe_sequence.h"

namespace kerf::cycles::probing {

namespace {

const Vec3 kDown(0.0, 0.0, -1.0);

// The moves the TT cycles share: the clearance height above the stylus, the spindle for a
// rotating or a stationary tool, and the touches.
class TtSequence {
public:
    TtSequence(int cycle, double clearanceZ, const ToolProbeData& tt, double positioningLength,
               ToolProbingMachine& machine)
        : m_cycle(cycle), m_tt(tt), m_positioningLength(positioningLength), m_machine(machine) {
        // A clearance height below the stylus's safety zone is raised to it (spec 7.1).
        m_clearanceGauge = std::max(clearanceZ, tt.top.z() + tt.safetyDistance) + positioningLength;
    }

    // Up to the clearance height, over (x, y), then down to the tool-tip height `tipZ`.
    void approach(double x, double y, double tipZ) {
        Vec3 at = m_machine.gauge();
        if (at.z() < m_clearanceGauge) {
            at.z() = m_clearanceGauge;
            m_machine.moveTo(at);
        }
        m_machine.moveTo(Vec3(x, y, at.z()));
        m_machine.moveTo(Vec3(x, y, tipZ + m_positioningLength));
    }

    void retract() {
        Vec3 at = m_machine.gauge();
        if (at.z() < m_clearanceGauge) {
            at.z() = m_clearanceGauge;
            m_machine.moveTo(at);
        }
    }

    // The rotating tool's speed and probing feed (spec 7.1, ConstantTolerance), or the
    // stationary spindle's feed.
    double startSpindle(bool rotating, double radius, double cuttingDirection) {
        if (!rotating || radius <= 0.0) {
            m_machine.spindle(canon::SpindleDirection::Stopped, 0.0);
            return m_tt.probingFeed;
        }
        double rpm = m_tt.maxPeripheralSpeed / (radius * 0.0063);
        if (m_tt.maxRpm > 0.0) rpm = std::min(rpm, m_tt.maxRpm);
        m_machine.spindle(cuttingDirection < 0.0 ? canon::SpindleDirection::Clockwise
                                                 : canon::SpindleDirection::CounterClockwise,
                          rpm);
        return m_tt.measureTolerance * rpm;
    }

    void stopSpindle() { m_machine.spindle(canon::SpindleDirection::Stopped, 0.0); }

    // A touch of at most twice the safety distance: the gauge point at the trigger.
    std::optional<CycleError> touch(const Vec3& direction, double feed, Vec3& trigger) {
        if (m_machine.deflected()) {
            return probingError(m_cycle, "PRB-002",
                                KERF_TR_NOOP("cycle {1}: stylus already deflected"));
        }
        const double path = 2.0 * m_tt.safetyDistance;
        auto hit = m_machine.touch(direction, path, feed);
        if (!hit) {
            return probingError(m_cycle, "PRB-001",
                                KERF_TR_NOOP("cycle {1}: touch point not reached within the "
                                             "measuring path DIST = {2} mm"),
                                {std::to_string(path)});
        }
        trigger = *hit;
        return std::nullopt;
    }

private:
    int m_cycle;
    const ToolProbeData& m_tt;
    double m_positioningLength;
    ToolProbingMachine& m_machine;
    double m_clearanceGauge = 0.0;
};

// Length: the end face onto the top of the stylus, the tool axis offset by R-OFFS (a rotating
// tool whose longest tooth sweeps the plate) or over the centre (stationary). With Q341 every
// tooth is touched at its own spindle orientation; the longest counts (spec 7, impl. note).
std::optional<CycleError> measureLength(TtSequence& tt, const ToolMeasurementRequest& request,
                                        const ToolProbeData& data, const MeasuredToolData& tool,
                                        ToolProbingMachine& machine, double& length) {
    const double offset = tool.radiusOffset.value_or(tool.radius);
    tt.approach(data.top.x() + offset, data.top.y(), data.top.z() + data.safetyDistance);
    const double feed = tt.startSpindle(offset != 0.0, tool.radius, tool.cuttingDirection);
    Vec3 trigger;
    if (auto e = tt.touch(kDown, feed, trigger)) return e;
    length = trigger.z() - data.top.z();
    if (request.teeth && tool.cutterCount > 0) {
        tt.stopSpindle();
        for (int tooth = 0; tooth < tool.cutterCount; ++tooth) {
            machine.orientSpindle(360.0 * tooth / tool.cutterCount);
            if (auto e = tt.touch(kDown, data.probingFeed, trigger)) return e;
            length = std::max(length, trigger.z() - data.top.z());
        }
    }
    tt.stopSpindle();
    tt.retract();
    return std::nullopt;
}

// Radius: the end face `offsetToolAxis` (+ L-OFFS) below the top of the stylus, beside it in -X,
// touching along +X; the rotating tool's longest tooth, or each tooth with Q341. CUT = 0 measures
// with a stationary spindle (diamond tools).
std::optional<CycleError> measureRadius(TtSequence& tt, const ToolMeasurementRequest& request,
                                        const ToolProbeData& data, const MeasuredToolData& tool,
                                        ToolProbingMachine& machine, double& radius) {
    const double half = data.diameter / 2.0;
    const double beside = half + tool.radius + tool.deltaRadius + data.safetyDistance;
    tt.approach(data.top.x() - beside, data.top.y(),
                data.top.z() - data.offsetToolAxis - tool.lengthOffset);
    const double feed = tt.startSpindle(tool.cutterCount > 0, tool.radius, tool.cuttingDirection);
    const Vec3 plus(1.0, 0.0, 0.0);
    Vec3 trigger;
    if (auto e = tt.touch(plus, feed, trigger)) return e;
    const double face = data.top.x() - half;
    radius = face - trigger.x();
    if (request.teeth && tool.cutterCount > 0) {
        tt.stopSpindle();
        for (int tooth = 0; tooth < tool.cutterCount; ++tooth) {
            machine.orientSpindle(360.0 * tooth / tool.cutterCount);
            if (auto e = tt.touch(plus, data.probingFeed, trigger)) return e;
            radius = std::max(radius, face - trigger.x());
        }
    }
    tt.stopSpindle();
    tt.retract();
    return std::nullopt;
}

// Spec 7, shared TT evaluation: a tolerance of 0 is not checked.
int toolStatus(double deviation, double wear, double breakage) {
    if (breakage > 0.0 && std::abs(deviation) > breakage) return 2;
    if (wear > 0.0 && std::abs(deviation) > wear) return 1;
    return 0;
}

}  // namespace

std::optional<CycleError> measureTool(int cycle, const ToolMeasurementRequest& request,
                                      const ToolProbeData& tt, const MeasuredToolData& tool,
                                      ToolProbingMachine& machine, ToolMeasurementResult& result) {
    TtSequence sequence(cycle, request.clearanceZ, tt, tool.length + tool.deltaLength, machine);
    // Cycle 33/483 measures the radius first, then the length.
    if (request.radius) {
        double radius = 0.0;
        if (auto e = measureRadius(sequence, request, tt, tool, machine, radius)) return e;
        result.radius = radius;
    }
    if (request.length) {
        double length = 0.0;
        if (auto e = measureLength(sequence, request, tt, tool, machine, length)) return e;
        result.length = length;
    }
    if (request.mode == 0) {
        if (result.length) {
            result.newLength = *result.length;
            result.newDeltaLength = 0.0;
        }
        if (result.radius) {
            result.newRadius = *result.radius;
            result.newDeltaRadius = 0.0;
        }
        return std::nullopt;
    }
    if (result.length) {
        result.lengthDeviation = *result.length - tool.length;
        result.status = std::max(
            result.status, toolStatus(result.lengthDeviation, tool.lengthWear, tool.lengthBreak));
    }
    if (result.radius) {
        result.radiusDeviation = *result.radius - tool.radius;
        result.status = std::max(
            result.status, toolStatus(result.radiusDeviation, tool.radiusWear, tool.radiusBreak));
    }
    if (request.mode == 1) {
        if (result.length) result.newDeltaLength = result.lengthDeviation;
        if (result.radius) result.newDeltaRadius = result.radiusDeviation;
        result.lock = result.status > 0;
    }
    return std::nullopt;
}

std::optional<CycleError> calibrateToolProbe(int cycle, double clearanceZ, const ToolProbeData& tt,
                                             const MeasuredToolData& tool,
                                             ToolProbingMachine& machine,
                                             ToolProbeData& calibrated) {
    // The calibration tool is a pin: touched with the spindle stopped, its L and R exact.
    TtSequence sequence(cycle, clearanceZ, tt, tool.length + tool.deltaLength, machine);
    const double pinRadius = tool.radius + tool.deltaRadius;
    sequence.approach(tt.top.x(), tt.top.y(), tt.top.z() + tt.safetyDistance);
    const double feed = sequence.startSpindle(false, 0.0, 0.0);
    Vec3 trigger;
    if (auto e = sequence.touch(kDown, feed, trigger)) return e;
    calibrated = tt;
    const double top = trigger.z() - tool.length - tool.deltaLength;
    // In the plane: a square around the stylus with a touch in the middle of each side.
    const double a = tt.diameter / 2.0 + pinRadius + tt.safetyDistance;
    const double cx = tt.top.x();
    const double cy = tt.top.y();
    sequence.retract();
    sequence.approach(cx - a, cy, top - tt.offsetToolAxis);
    const double z = machine.gauge().z();
    struct Side {
        Vec2 start, corner, direction;
    };
    const Side sides[] = {{{cx - a, cy}, {cx - a, cy - a}, {1.0, 0.0}},
                          {{cx, cy - a}, {cx + a, cy - a}, {0.0, 1.0}},
                          {{cx + a, cy}, {cx + a, cy + a}, {-1.0, 0.0}},
                          {{cx, cy + a}, {cx - a, cy + a}, {0.0, -1.0}}};
    double surface[4] = {};
    for (size_t i = 0; i < 4; ++i) {
        machine.moveTo(Vec3(sides[i].start.x(), sides[i].start.y(), z));
        const Vec3 direction(sides[i].direction.x(), sides[i].direction.y(), 0.0);
        if (auto e = sequence.touch(direction, feed, trigger)) return e;
        const Vec2 face = Vec2(trigger.x(), trigger.y()) + pinRadius * sides[i].direction;
        surface[i] = i % 2 == 0 ? face.x() : face.y();
        machine.moveTo(Vec3(sides[i].corner.x(), sides[i].corner.y(), z));
    }
    const double centreX = (surface[0] + surface[2]) / 2.0;
    const double centreY = (surface[1] + surface[3]) / 2.0;
    // A disc touched on lines through the nominal centre: each pair is a chord, off the real
    // centre by the other axis's error.
    const double halfX = (surface[2] - surface[0]) / 2.0;
    const double halfY = (surface[3] - surface[1]) / 2.0;
    double diameter = halfX + halfY;
    if (!tt.cube) {
        diameter = std::hypot(halfX, cy - centreY) + std::hypot(halfY, cx - centreX);
    }
    calibrated.top = Vec3(centreX, centreY, top);
    calibrated.diameter = diameter;
    sequence.retract();
    machine.moveTo(Vec3(centreX, centreY, machine.gauge().z()));
    return std::nullopt;
}

}  // namespace kerf::cycles::probing
