#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "core/canon/commands.h"
#include "core/machine/machine_config.h"
#include "motion/kinematics/machine_model.h"
#include "motion/planner/planner.h"
#include "motion/port/drive_bus.h"
#include "motion/port/motion_status.h"
#include "motion/port/operator_command.h"
#include "motion/port/seqlock.h"
#include "motion/rt/servo_cycle.h"
#include "motion/sim/sim_drive_set.h"

// The planner and the servo cycle in real time, for the HMI: the servo cycle runs in its own
// thread at the configured period (SCHED_FIFO and locked memory when the system allows it; their
// absence is reported, not fatal), on the simulated drives or on a DriveBus given by the caller.
// Nothing is allocated, locked or logged in that thread after start().
//
// Threads: the constructor, start() and stop() in the owning thread; submit(), flush(), pump(),
// command() and nextEvent() in one task thread; status() and report() in any thread.
namespace kerf::motion {

struct RealtimeOptions {
    MotionOptions motion;
    SimDriveOptions drives;
    AxisVector startPosition{};  // simulated drives: tool tip at start
    // Simulated drives: the probe touches while this says the tool tip (workpiece coordinates)
    // is inside the workpiece. Empty: the machine file's [simulation.probe] box, if any.
    std::function<bool(const AxisVector& tip)> probeSurface;
    int priority = 80;  // SCHED_FIFO priority requested
    bool lockMemory = true;
};

struct RealtimeReport {
    bool running = false;
    bool realtimePriority = false;  // SCHED_FIFO granted
    bool memoryLocked = false;      // mlockall succeeded
    std::string note;               // why not, for the operator's diagnostics screen
};

class RealtimeMachine {
public:
    // `bus` == nullptr: simulated drives.
    RealtimeMachine(const machine::MachineConfig& config, RealtimeOptions options,
                    DriveBus* bus = nullptr);
    ~RealtimeMachine();
    RealtimeMachine(const RealtimeMachine&) = delete;
    RealtimeMachine& operator=(const RealtimeMachine&) = delete;

    bool start();
    void stop();
    RealtimeReport report() const;

    // Task thread: plan a command (false: refused, see planner().diagnostics()), then move what
    // is planned into the servo ring as far as it has room. Call pump() periodically while the
    // program runs (the ring holds a bounded amount); flush() at a sync point or the end.
    bool submit(const canon::Command& command);
    void flush();
    void pump();
    bool drained() const;  // nothing planned or queued, the axes at rest
    const Planner& planner() const { return m_planner; }
    Planner& planner() { return m_planner; }

    bool command(const OperatorCommand& command);
    // Simulated drives: press or release the emergency-stop button (false on a real bus).
    bool setEmergencyStopButton(bool pressed);
    std::optional<MotionEvent> nextEvent();

    MotionStatus status() const { return m_status.read(); }
    const MachineModel& model() const { return m_model; }

private:
    void run();
    AxisVector tipOf(const std::array<double, kMaxJoints>& joints) const;

    MachineModel m_model;
    RealtimeOptions m_options;
    std::unique_ptr<SimDriveSet> m_simDrives;
    DriveBus& m_bus;
    std::unique_ptr<ItemRing> m_items;
    CommandRing m_commands;
    EventRing m_events;
    ServoCycle m_servo;
    Planner m_planner;
    std::optional<MotionItem> m_backlog;  // planned, waiting for room in the ring
    Seqlock<MotionStatus> m_status;
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    std::atomic<bool> m_running{false};
    std::atomic<bool> m_priority{false};
    std::atomic<bool> m_locked{false};
    // The planned tool length, for the probe surface test in the servo thread.
    std::atomic<double> m_toolLength{0.0};
    // What the probe touches on the current probe move (canon::ProbeMove::surface): owned by
    // the task thread, tested by the servo thread through the pointer.
    std::shared_ptr<const canon::ProbeSurface> m_probeTargetOwner;
    std::shared_ptr<const canon::ProbeSurface> m_retiredProbeTarget;
    std::atomic<const canon::ProbeSurface*> m_probeTarget{nullptr};
    std::string m_note;
};

}  // namespace kerf::motion
