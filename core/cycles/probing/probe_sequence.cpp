#include "core/cycles/probing/probe_sequence.h"

#include "core/base/translate.h"

namespace kerf::cycles::probing {

CycleError probingError(int cycle, const char* code, const char* messageTemplate,
                        std::vector<std::string> args) {
    args.insert(args.begin(), std::to_string(cycle));
    return CycleError{code, messageTemplate, std::move(args)};
}

CycleError coincidentTouches(int cycle) {
    return probingError(cycle, "cycle-parameter",
                        KERF_TR_NOOP("cycle {1}: the two points of a measured line coincide"));
}

ProbeSequence::ProbeSequence(int cycle, const CycleValues& values, const ProbeData& probe,
                             ProbingMachine& machine)
    : m_cycle(cycle), m_values(values), m_probe(probe), m_machine(machine) {}

double ProbeSequence::standOff() const {
    return m_probe.ballRadius + m_probe.setUp + m_values.number(320);
}

void ProbeSequence::approach(const Vec3& target) {
    const Vec3 now = m_machine.ballCentre();
    const bool viaClearance = m_first ? now.z() < clearanceCentre() : m_values.integer(301) == 1;
    Vec3 at = now;
    if (viaClearance) {
        at.z() = std::max(now.z(), clearanceCentre());
        m_machine.moveTo(at);
    }
    m_machine.moveTo(Vec3(target.x(), target.y(), at.z()));
    m_machine.moveTo(target);
    m_first = false;
}

std::optional<CycleError> ProbeSequence::touchFrom(const Vec3& direction, Vec3& trigger) {
    if (m_machine.deflected()) {
        return probingError(m_cycle, "PRB-002",
                            KERF_TR_NOOP("cycle {1}: stylus already deflected"));
    }
    auto hit = m_machine.touch(direction, m_probe.maxPath);
    if (!hit) {
        return probingError(m_cycle, "PRB-001",
                            KERF_TR_NOOP("cycle {1}: touch point not reached within the "
                                         "measuring path DIST = {2} mm"),
                            {std::to_string(m_probe.maxPath)});
    }
    trigger = *hit;
    return std::nullopt;
}

std::optional<CycleError> ProbeSequence::touchInPlane(const Vec2& nominal, const Vec2& direction,
                                                      Vec2& surface, const Vec2* prePosition) {
    const Vec2 d = direction.normalized();
    const Vec2 start = prePosition != nullptr ? *prePosition : nominal - standOff() * d;
    approach(Vec3(start.x(), start.y(), measuringHeight()));
    Vec3 trigger;
    if (auto e = touchFrom(Vec3(d.x(), d.y(), 0.0), trigger)) return e;
    surface = Vec2(trigger.x(), trigger.y()) + m_probe.ballRadius * d;
    return std::nullopt;
}

std::optional<CycleError> ProbeSequence::touchDown(const Vec2& at, double nominalW,
                                                   double& surfaceW) {
    // Over the point at the clearance height, then down to the pre-position above the surface.
    const Vec3 start(at.x(), at.y(), nominalW + standOff());
    const Vec3 now = m_machine.ballCentre();
    const double high = std::max(now.z(), clearanceCentre());
    m_machine.moveTo(Vec3(now.x(), now.y(), high));
    m_machine.moveTo(Vec3(at.x(), at.y(), high));
    m_machine.moveTo(start);
    m_first = false;
    Vec3 trigger;
    if (auto e = touchFrom(Vec3(0.0, 0.0, -1.0), trigger)) return e;
    surfaceW = trigger.z() - m_probe.ballRadius;
    return std::nullopt;
}

std::optional<CycleError> ProbeSequence::touchFromPoint(const Vec3& start, const Vec3& direction,
                                                        Vec3& ball) {
    approach(start);
    return touchFrom(direction.normalized(), ball);
}

void ProbeSequence::retract() {
    Vec3 at = m_machine.ballCentre();
    if (at.z() < clearanceCentre()) {
        at.z() = clearanceCentre();
        m_machine.moveTo(at);
    }
}

}  // namespace kerf::cycles::probing
