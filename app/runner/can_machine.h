#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/base/expected.h"
#include "core/canon/commands.h"
#include "core/interp/interpreter.h"
#include "core/machine/machine_config.h"
#include "drivers/setup/can_sim_drive_set.h"
#include "motion/kinematics/machine_model.h"
#include "motion/port/motion_status.h"

// The whole drive chain in simulated time: motion's planner and servo cycle write their setpoints
// through the CANopen master to simulated CiA 402 drives on the virtual CAN bus, the way motion's
// SimulatedMachine runs them on its own simulated drives. The interpreter streams canonical
// commands into consume(); drain() runs until everything queued is executed. After a drive fault
// (or any stop of the drive set) the planner is flushed, further commands are dropped, and the
// simulation runs on until every drive has come to rest under its quick stop (bounded in
// simulated time), so the result says where each one stopped. One thread (the caller's); used by
// `kerf run --drives can-sim` and the tests.
namespace kerf::app {

// One drive after a stop of the drive set.
struct DriveRest {
    int joint = -1;
    char letter = 'X';    // axis letter; 'S' for the spindle
    double atStop = 0.0;  // joint position (mm or deg) when the quick stop went out
    double atRest = 0.0;  // where its feedback came to rest (its last feedback if unknown)
    drivers::cia402::Standstill standstill = drivers::cia402::Standstill::Moving;
};

struct StopOutcome {
    double stoppedS = 0.0;  // simulated time from the end of the boot to the quick stop
    double restS = 0.0;     // from the quick stop until every reporting drive was at rest
    double limitS = 0.0;    // how long the simulation waited at most
    motion::AxisVector tipAtStop{};
    std::vector<DriveRest> drives;
    bool allAtRest() const;
};

struct CanRunResult {
    motion::AxisVector finalPosition{};  // tool tip from the drives' feedback
    motion::AxisVector commandedPosition{};
    double durationS = 0.0;            // simulated time from the end of the boot
    double maxFollowingErrorMm = 0.0;  // while the drives followed the setpoints
    double busLoad = 0.0;              // measured share of the bus since power-on
    motion::MotionMode mode = motion::MotionMode::Idle;
    bool stopped = false;             // the drive set stopped (fault, lost node ...)
    SourceLocation stoppedAt;         // the block being executed when it stopped
    std::optional<StopOutcome> stop;  // where every drive came to rest after the stop
    bool refused = false;             // the planner refused a block (see diagnostics)
    bool timeLimit = false;           // the simulated-time limit ended the run
    DiagnosticList diagnostics;       // drive, planner and motion diagnostics
};

class CanMachine final : public canon::Sink {
public:
    // Creates the drive set (refusing a bus above 80 % load), puts the joints where `startTip`
    // (workpiece coordinates) says and boots the drives; fails with the reason (a boot failure
    // names node and object). `motion` holds the work offset, as for motion's own simulation.
    static Expected<std::unique_ptr<CanMachine>> create(const machine::MachineConfig& config,
                                                        drivers::CanSimOptions options,
                                                        const motion::AxisVector& startTip,
                                                        const motion::MotionOptions& motion = {});
    ~CanMachine() override;
    CanMachine(const CanMachine&) = delete;
    CanMachine& operator=(const CanMachine&) = delete;

    void consume(const canon::Command& command) override;
    // Runs until every queued command is executed and the axes stand still (or the drives
    // stopped, and then until they came to rest); returns the machine data the interpreter
    // asked for.
    interp::WorldSnapshot drain();
    // Runs on for `seconds` without new commands (tests: nothing may move after a stop).
    void runFor(double seconds);
    // True once the drive set stopped, motion faulted or the simulated-time limit was reached.
    bool stopped() const;
    // The planner refused a block (a soft limit ...): nothing after it is executed.
    bool refused() const;
    // Drains, closes the CAN trace and collects the result.
    CanRunResult finish();

    drivers::CanSimDriveSet& drives();
    const motion::MotionStatus& status() const;

private:
    struct Chain;
    explicit CanMachine(std::unique_ptr<Chain> chain);
    std::unique_ptr<Chain> m_chain;
};

}  // namespace kerf::app
