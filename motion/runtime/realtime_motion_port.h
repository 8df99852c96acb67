#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "core/task/motion_port.h"
#include "motion/runtime/realtime_machine.h"

// task::MotionPort over the real-time machine (simulated drives unless a DriveBus is given): the
// program run and the HMI's manual operation drive the servo thread through it. Its events
// become the progress, the world snapshot (probe results) and the fault text; what the operator
// sees is the status snapshot, completed with what the port remembers of the submitted blocks
// (their end points, feeds and tools) for DIST, programmed F and the active tool.
//
// Threads: construction and destruction in the owning thread (they start and stop the servo
// thread); everything else in one task thread (the HMI's, serviced by a timer).
namespace kerf::motion {

class RealtimeMotionPort final : public task::MotionPort {
public:
    RealtimeMotionPort(const machine::MachineConfig& config, RealtimeOptions options,
                       DriveBus* bus = nullptr);
    ~RealtimeMotionPort() override;

    bool submit(const canon::Command& command) override;
    bool hasRoom() const override;
    void flush() override;
    void pump() override;
    bool drained() const override;
    interp::WorldSnapshot world() const override;
    Progress progress() const override;
    bool latchesProbe() const override { return true; }

    void cycleStart() override;
    void feedHold() override;
    void quickStop() override;
    void emergencyStop() override;
    bool machineOn() override;
    bool setEmergencyStopButton(bool pressed) override;
    void setSingleBlock(bool on) override;
    void setSingleBlockEveryBlock(bool on) override;

    void setFeedOverride(double fraction) override;
    void setRapidOverride(double fraction) override;
    void setSpindleOverride(double fraction) override;
    bool jogContinuous(Axis axis, double velocityFraction) override;
    bool jogStop(Axis axis) override;
    bool jogIncrement(Axis axis, double distance) override;
    bool home(std::optional<Axis> axis) override;
    // At once in the servo cycle (not queued): Spindle off stops a spindle that still ramps.
    bool manualSpindle(const canon::SpindleControl& spindle) override;
    bool manualCoolant(const canon::CoolantControl& coolant) override;
    task::MachineStatus status() const override;

    RealtimeMachine& machine() { return *m_machine; }
    const RealtimeReport report() const { return m_machine->report(); }

private:
    // What the port remembers of a submitted block until motion has passed it.
    struct Submitted {
        SourceLocation block;
        std::optional<AxisVector> target;
        double feedMmPerMin = 0.0;
        std::optional<int> tool;
        std::optional<double> toolLength;
        std::optional<double> spindleRpm;
        double surfaceSpeed = 0.0;  // m/min under constant surface speed (G96), else 0
    };

    int jointOf(Axis axis) const;
    bool manualAllowed() const;
    bool withoutProgram() const;      // nothing planned, queued or executing, the axes at rest
    bool programInterrupted() const;  // held or stopped, or jogged away from there
    void handle(const MotionEvent& event);
    void prepareForCommands();
    void stopProgrammedSpindle();
    void retire(const Submitted& done);
    void followExecution(const MotionStatus& now);

    std::unique_ptr<RealtimeMachine> m_machine;
    machine::MachineConfig m_config;
    AxisVector m_workOffset{};
    // The planner starts from the servo's position before the next command (after manual
    // motion, an abort or a refusal).
    bool m_replan = false;
    std::string m_fault;
    interp::WorldSnapshot m_probe;
    std::deque<Submitted> m_submitted;
    Submitted m_executing;  // the block being executed (or the last one)
    int m_tool = 0;
    double m_toolLength = 0.0;
    double m_programmedRpm = 0.0;
    double m_programmedSurfaceSpeed = 0.0;  // m/min, 0: constant speed
    // The feed mode and spindle speed as submitted (ahead of execution), for the feed shown.
    bool m_feedPerRevolution = false;
    double m_submittedRpm = 0.0;
    double m_feedOverride = 1.0;
    double m_rapidOverride = 1.0;
    bool m_singleBlock = false;
};

}  // namespace kerf::motion
