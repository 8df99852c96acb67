#pragma once

#include <array>
#include <atomic>
#include <functional>

#include "motion/kinematics/machine_model.h"
#include "motion/port/drive_bus.h"

// Simulated drives, the default DriveBus: per joint a CiA 402-like state machine and a servo
// model (position loop with gain kv and velocity feed-forward, one cycle of bus delay) whose
// following error is visible in the feedback; a home switch per joint and a touch probe.
// advance() runs one period of the drives; it and the DriveBus functions are called by the
// thread that runs the servo cycle.
namespace kerf::motion {

struct SimDriveOptions {
    double positionGainPerS = 60.0;  // kv
    double feedForward = 1.0;        // share of the setpoint velocity fed forward
    int enableCycles = 3;            // cycles from the enable request to operation enabled
    double quickStopDecel = 5000.0;  // units/s^2, the drives' own quick-stop ramp
};

class SimDriveSet final : public DriveBus {
public:
    SimDriveSet(const MachineModel& model, const SimDriveOptions& options);

    // True position of every joint (before the homing offset) at start.
    void setTruePositions(const std::array<double, kMaxJoints>& positions);
    // Probe model: true when the tool tip (in joint space) touches the workpiece.
    using ProbeSurface = std::function<bool(const std::array<double, kMaxJoints>& joints)>;
    void setProbeSurface(ProbeSurface surface) { m_probeSurface = std::move(surface); }
    // What ends the next probe moves: the probe touching (G75) or no longer touching (G76).
    // Like a touch probe's level input: armed while already in that state, it latches at once.
    enum class ProbeEvent : uint8_t { Touch, Release };
    void setProbeEvent(ProbeEvent event) noexcept { m_probeEvent = event; }
    ProbeEvent probeEvent() const noexcept { return m_probeEvent; }
    void injectFault(int joint, uint16_t code) noexcept;
    // The simulated E-stop button: pressed (chain open) or released. Any thread.
    void setEmergencyStopPressed(bool pressed) noexcept { m_emergencyStop.store(pressed); }

    // One period of the drives (after the servo cycle wrote its setpoints).
    void advance(double dt) noexcept;

    double truePosition(int joint) const noexcept { return m_true[static_cast<size_t>(joint)]; }
    double reportedPosition(int joint) const noexcept;

    int jointCount() const noexcept override { return m_count; }
    BusResult read(std::span<JointFeedback> feedback) noexcept override;
    BusResult write(std::span<const JointSetpoint> setpoints) noexcept override;
    void request(DriveRequest request) noexcept override;
    void setPosition(int joint, double position) noexcept override;
    void armProbe(bool armed) noexcept override;
    bool emergencyStopOpen() const noexcept override { return m_emergencyStop.load(); }

private:
    const MachineModel& m_model;
    SimDriveOptions m_options;
    int m_count;
    std::array<double, kMaxJoints> m_true{};
    std::array<double, kMaxJoints> m_offset{};  // reported = true + offset
    std::array<double, kMaxJoints> m_velocity{};
    std::array<double, kMaxJoints> m_setpoint{};
    std::array<double, kMaxJoints> m_previousSetpoint{};
    std::array<DriveState, kMaxJoints> m_state{};
    std::array<uint16_t, kMaxJoints> m_fault{};
    std::array<double, kMaxJoints> m_latch{};
    int m_enableCountdown = -1;
    bool m_probeArmed = false;
    bool m_probeWasHit = false;  // the awaited probe state held at the last period's end
    ProbeEvent m_probeEvent = ProbeEvent::Touch;
    bool m_latched = false;
    bool m_haveSetpoint = false;
    ProbeSurface m_probeSurface;
    std::atomic<bool> m_emergencyStop{false};
};

}  // namespace kerf::motion
