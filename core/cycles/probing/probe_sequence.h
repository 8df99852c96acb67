#pragma once

#include "core/cycles/probing/probing_cycle.h"

namespace kerf::cycles::probing {

// The moves every 4xx cycle shares (spec 1.5, 1.7, 1.8): the positioning logic around the
// clearance height Q260, pre-positioning by r_b + SET_UP + Q320 before each touch, the touch
// within DIST and the compensation of the ball radius.
class ProbeSequence {
public:
    ProbeSequence(int cycle, const CycleValues& values, const ProbeData& probe,
                  ProbingMachine& machine);

    double ballRadius() const { return m_probe.ballRadius; }
    // r_b + SET_UP + Q320: how far a pre-position lies from the nominal surface point.
    double standOff() const;
    double measuringHeight() const { return m_values.number(261); }

    // A touch in the working plane at the measuring height: pre-positions `standOff()` before the
    // nominal surface point `nominal` (u, v), probes along `direction` and gives the touched
    // surface point. `fromCentre`: the probe stays at measuring height from one touch to the next
    // (inside features too small to pre-position near the wall).
    std::optional<CycleError> touchInPlane(const Vec2& nominal, const Vec2& direction,
                                           Vec2& surface, const Vec2* prePosition = nullptr);
    // A touch along -w onto a nominal surface height `nominalW` at (u, v): gives the surface
    // height.
    std::optional<CycleError> touchDown(const Vec2& at, double nominalW, double& surfaceW);
    // A touch along the unit `direction` from `start`, reached by the positioning logic: the
    // ball centre at the trigger (444's touch along a surface normal).
    std::optional<CycleError> touchFromPoint(const Vec3& start, const Vec3& direction, Vec3& ball);
    // A touch from where the probe stands along the unit `direction` within DIST (PRB-001,
    // PRB-002): the ball centre at the trigger.
    std::optional<CycleError> touchFrom(const Vec3& direction, Vec3& trigger);
    // Back to the clearance height at the end of the cycle.
    void retract();

private:
    // Ball centre to `target` following the positioning logic; `target` at measuring height.
    void approach(const Vec3& target);
    double clearanceCentre() const { return m_values.number(260) + m_probe.ballRadius; }

    int m_cycle;
    const CycleValues& m_values;
    const ProbeData& m_probe;
    ProbingMachine& m_machine;
    bool m_first = true;
};

// The error of a probing cycle with code `code` (PRB-nnn of spec 1.16).
CycleError probingError(int cycle, const char* code, const char* messageTemplate,
                        std::vector<std::string> args = {});
// Two touches (or measured centres) at one spot: the cycle's parameters give no line.
CycleError coincidentTouches(int cycle);

}  // namespace kerf::cycles::probing
