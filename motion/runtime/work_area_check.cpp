#include "motion/runtime/work_area_check.h"

#include "motion/runtime/machine_realtime_options.h"

namespace kerf::motion {

WorkAreaCheck::WorkAreaCheck(const MachineModel& model)
    : m_model(model), m_planner(m_model, PlannerRole::JudgeOnly) {}

void WorkAreaCheck::start(const Pose& tip) {
    m_planner.setPosition(tip.values);
}

bool WorkAreaCheck::accept(const canon::Command& command) {
    if (m_planner.refused()) return false;
    // Until a sync point says otherwise, a probe move ends where it was programmed to.
    if (m_planner.needsPosition()) m_planner.setPosition(m_planner.position());
    if (!m_planner.add(command)) return false;
    while (m_planner.next()) {
    }
    return true;
}

void WorkAreaCheck::resumeAt(const Pose& tip) {
    m_planner.flush();
    while (m_planner.next()) {
    }
    m_planner.setPosition(tip.values);
}

Pose WorkAreaCheck::position() const {
    Pose pose;
    pose.values = m_planner.position();
    return pose;
}

std::unique_ptr<task::MoveCheck> makeWorkAreaCheck(const machine::MachineConfig& config,
                                                   const Pose& originInMachine) {
    MotionOptions options = machineRealtimeOptions(config).motion;
    options.workOffset = originInMachine.values;
    return std::make_unique<WorkAreaCheck>(makeMachineModel(config, options));
}

}  // namespace kerf::motion
