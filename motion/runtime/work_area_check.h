#pragma once

#include <memory>

#include "core/machine/machine_config.h"
#include "core/task/move_check.h"
#include "motion/kinematics/machine_model.h"
#include "motion/planner/planner.h"

namespace kerf::motion {

// task::MoveCheck over a planner of its own that executes nothing: every command is judged as
// the machine's planner judges it (PlannerRole::JudgeOnly: the same checks, without the smoothing
// and look-ahead that never refuse anything), so a move beyond a soft limit, an axis the machine
// lacks, a feed move without feed ... are refused with the planner's own message naming the block.
// `kerf run --motion/--drives` (app/runner/SoftLimitGate) and the HMI's test run use it.
// One thread.
class WorkAreaCheck final : public task::MoveCheck {
public:
    explicit WorkAreaCheck(const MachineModel& model);
    WorkAreaCheck(const WorkAreaCheck&) = delete;
    WorkAreaCheck& operator=(const WorkAreaCheck&) = delete;

    void start(const Pose& tip) override;
    bool accept(const canon::Command& command) override;
    void resumeAt(const Pose& tip) override;
    Pose position() const override;
    bool refused() const override { return m_planner.refused(); }
    DiagnosticList refusal() const override { return m_planner.diagnostics(); }

private:
    MachineModel m_model;  // the planner refers to it
    Planner m_planner;
};

// The check Program run applies in the HMI: the machine's model as the real-time machine builds
// it (machineRealtimeOptions), with the workpiece origin at `originInMachine`.
std::unique_ptr<task::MoveCheck> makeWorkAreaCheck(const machine::MachineConfig& config,
                                                   const Pose& originInMachine);

}  // namespace kerf::motion
