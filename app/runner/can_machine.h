#pragma once

#include <memory>
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
// (or any stop of the drive set) the planner is flushed and further commands are dropped: nothing
// keeps moving. One thread (the caller's); used by `kerf run --drives can-sim` and the tests.
namespace kerf::app {

struct CanRunResult {
    motion::AxisVector finalPosition{};  // tool tip from the drives' feedback
    motion::AxisVector commandedPosition{};
    double durationS = 0.0;  // simulated time from the end of the boot
    double maxFollowingErrorMm = 0.0;
    double busLoad = 0.0;  // measured share of the bus since power-on
    motion::MotionMode mode = motion::MotionMode::Idle;
    bool stopped = false;        // the drive set stopped (fault, lost node ...)
    SourceLocation stoppedAt;    // the block being executed when it stopped
    bool refused = false;        // the planner refused a block (see diagnostics)
    DiagnosticList diagnostics;  // drive, planner and motion diagnostics
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
    // stopped); returns the machine data the interpreter asked for.
    interp::WorldSnapshot drain();
    // Runs on for `seconds` without new commands (tests: nothing may move after a stop).
    void runFor(double seconds);
    // True once the drive set stopped or motion faulted.
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
