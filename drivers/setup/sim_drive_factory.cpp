#include "drivers/setup/sim_drive_factory.h"

#include <algorithm>

#include "drivers/canopen/sdo_abort.h"

namespace kerf::drivers {

sim::SimDriveConfig makeSimDriveConfig(const CanBusConfig& config, const CanJoint& joint) {
    sim::SimDriveConfig s;
    s.node = joint.node;
    if (config.vendorId) s.vendorId = *config.vendorId;
    if (config.productCode) s.productCode = *config.productCode;
    s.serial = joint.node;
    s.plant.maxVelocity = 1.5 * joint.maxVelocity * joint.countsPerUnit;
    s.plant.maxAcceleration = 3.0 * joint.maxAcceleration * joint.countsPerUnit;
    s.plant.frictionDecel = 0.5 * joint.maxAcceleration * joint.countsPerUnit;
    return s;
}

void injectDriveFault(sim::SimDrive& drive, const CanBusConfig& config, const CanJoint& joint,
                      FaultKind kind, std::chrono::nanoseconds now) {
    switch (kind) {
        case FaultKind::Heartbeat:
            drive.stopHeartbeat();
            break;
        case FaultKind::Emcy:
            drive.injectFault(0x4310, now);
            break;  // excess temperature drive
        case FaultKind::FollowingError:
            // Pushed away at 50 windows per second: beyond the window after 20 ms.
            drive.injectFollowingError(50.0 * std::max(joint.followingErrorWindow, 0.01) *
                                       joint.countsPerUnit);
            break;
        case FaultKind::Encoder:
            drive.injectEncoderLoss(now);
            break;
        case FaultKind::Pdo:
            drive.stopTpdos();
            break;
        case FaultKind::Silent:
            drive.goSilent();
            break;
        case FaultKind::SlowBoot:
            drive.setBootTime(std::chrono::seconds(6));
            break;
        case FaultKind::Identity:
            drive.setIdentity(config.vendorId.value_or(sim::kSimVendorId),
                              config.productCode.value_or(sim::kSimProductCode) + 1);
            break;
        case FaultKind::SdoAbort:
            drive.injectSdoAbort({0x1017, 0},
                                 static_cast<uint32_t>(canopen::SdoAbort::HardwareError));
            break;
        case FaultKind::BusOff:
        case FaultKind::ErrorPassive:
            break;
    }
}

}  // namespace kerf::drivers
