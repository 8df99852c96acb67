#pragma once

#include <array>
#include <functional>
#include <memory>

#include "drivers/setup/can_sim_drive_set.h"
#include "motion/port/motion_status.h"

// A simulated CAN drive set driven like motion's servo cycle does: read, setpoints, write, then
// one period of bus and drives. Tests move joints by setting targets.
namespace kerf::drivers::test {

class DriveRig {
public:
    explicit DriveRig(const machine::MachineConfig& config, CanSimOptions options = {});

    // Boots and enables every drive; false (with the reason in the test log) on failure.
    bool boot();
    // One servo cycle. With `write` false the cycle skips write(), as motion does in fault.
    motion::BusResult cycle(bool write = true);
    void run(double seconds, bool write = true);
    // Runs until `done` or the timeout; false on timeout.
    bool runUntil(const std::function<bool()>& done, double timeoutS);

    double& setpoint(int joint) { return m_setpoints[static_cast<size_t>(joint)].position; }
    const motion::JointFeedback& feedback(int joint) const {
        return m_feedback[static_cast<size_t>(joint)];
    }
    CanSimDriveSet& set() { return *m_set; }
    cia402::DriveBusAdapter& adapter() { return m_set->stack().adapter(); }
    double timeS() const { return m_set->timeS(); }
    double periodS() const { return m_periodS; }
    int joints() const { return m_joints; }

private:
    std::unique_ptr<CanSimDriveSet> m_set;
    std::array<motion::JointFeedback, motion::kMaxJoints> m_feedback{};
    std::array<motion::JointSetpoint, motion::kMaxJoints> m_setpoints{};
    double m_periodS = 0.001;
    int m_joints = 0;
};

}  // namespace kerf::drivers::test
