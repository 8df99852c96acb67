#include "tests/drivers/system/drive_rig.h"

#include <chrono>

#include <gtest/gtest.h>

namespace kerf::drivers::test {

DriveRig::DriveRig(const machine::MachineConfig& config, CanSimOptions options) {
    auto set = CanSimDriveSet::create(config, std::move(options));
    if (!set) {
        ADD_FAILURE() << set.error().message();
        return;
    }
    m_set = std::move(set).value();
    m_periodS = std::chrono::duration<double>(m_set->config().servoPeriod).count();
    m_joints = m_set->bus().jointCount();
}

bool DriveRig::boot() {
    if (!m_set) return false;
    if (MaybeError error = m_set->boot()) {
        ADD_FAILURE() << error->message();
        return false;
    }
    m_set->bus().read({m_feedback.data(), static_cast<size_t>(m_joints)});
    for (int j = 0; j < m_joints; ++j)
        setpoint(j) = feedback(j).position;
    return true;
}

motion::BusResult DriveRig::cycle(bool write) {
    auto joints = static_cast<size_t>(m_joints);
    motion::BusResult result = m_set->bus().read({m_feedback.data(), joints});
    if (write) m_set->bus().write({m_setpoints.data(), joints});
    m_set->advance(m_periodS);
    return result;
}

void DriveRig::run(double seconds, bool write) {
    auto cycles = static_cast<long>(seconds / m_periodS + 0.5);
    for (long i = 0; i < cycles; ++i)
        cycle(write);
}

bool DriveRig::runUntil(const std::function<bool()>& done, double timeoutS) {
    double end = timeS() + timeoutS;
    while (timeS() < end) {
        if (done()) return true;
        cycle();
    }
    return done();
}

}  // namespace kerf::drivers::test
