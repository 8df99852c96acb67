#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "core/interp/interpreter.h"
#include "core/machine/machine_config.h"
#include "motion/kinematics/machine_model.h"
#include "motion/port/motion_status.h"
#include "motion/port/operator_command.h"
#include "motion/sim/motion_recorder.h"
#include "motion/sim/sim_drive_set.h"

// The planner and the servo cycle on simulated drives in simulated time: a program runs faster
// than real time and deterministically (same commands, same samples). The interpreter streams
// canonical commands into consume(); drain() runs the simulation until everything queued is
// executed (sync points, end of program) and returns the machine data the interpreter asked for.
// Memory stays bounded: the planner holds back only the braking distance, the servo ring is fixed.
// One thread (the caller's); Qt-free.
namespace kerf::motion {

struct SimulationOptions {
    MotionOptions motion;
    SimDriveOptions drives;
    AxisVector startPosition{};  // tool tip at start, workpiece coordinates
    std::string samplesCsvPath;  // write every servo sample here (empty: no file)
    bool autoCycleStart = true;  // press cycle start at M0/M1/single-block stops
    bool measure = true;         // measure the samples for report() (a clock needs no peaks)
    // Simulated time from the program's start after which the run stops with an error.
    double maxSimulatedS = 24.0 * 3600.0;
    // Presses the simulated emergency-stop button this long (s) after the drives enabled (the
    // program's start); negative: never.
    double emergencyStopAtS = -1.0;
    // The workpiece for probing: true when the tool tip (workpiece coordinates) touches it.
    // Empty: the machine file's [simulation.probe] box, if it enables one.
    std::function<bool(const AxisVector& tip)> probeSurface;
    // Called after every servo cycle (tests).
    std::function<void(const Sample& sample, const MotionStatus& status)> onSample;
};

struct AxisReport {
    char letter = 'X';
    double maxVelocity = 0.0;  // per s, on the sampled setpoints
    double maxAccel = 0.0;
    double maxJerk = 0.0;
};

struct MotionReport {
    double durationS = 0.0;  // simulated time until everything was executed
    double feedTimeS = 0.0;  // start of the first feed move to the end of the last one
    double maxPathDeviationMm = 0.0;
    double maxFollowingErrorMm = 0.0;
    std::vector<AxisReport> axes;  // enabled axes in display order
    AxisVector finalPosition{};    // tool tip from the simulated drives' feedback
    uint64_t cycles = 0;
    uint32_t programmedMoves = 0;
    bool refused = false;  // the planner refused a block (see diagnostics)
    DiagnosticList diagnostics;
};

class SimulatedMachine final : public canon::Sink {
public:
    SimulatedMachine(const machine::MachineConfig& config, SimulationOptions options);
    ~SimulatedMachine() override;

    void consume(const canon::Command& command) override;
    // Runs until every queued command is executed and the axes stand still.
    interp::WorldSnapshot drain();
    MotionReport report() const;

    // Tests and tools: operator commands at the current simulated time, and running time on.
    void command(const OperatorCommand& command);
    void runFor(double seconds);
    // Runs cycles until `done` returns true (or the time limit); false on timeout.
    bool runUntil(const std::function<bool(const MotionStatus&)>& done, double timeoutS);
    const MotionStatus& status() const;
    const MachineModel& model() const;
    SimDriveSet& drives();
    double timeS() const;
    // Programmed moves the planner accepted so far (PathElement::moveIndex counts them).
    uint32_t acceptedMoves() const;
    // An emergency stop, a drive fault or the simulated-time limit ended the program: later
    // commands are dropped.
    bool halted() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace kerf::motion
