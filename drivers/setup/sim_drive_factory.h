#pragma once

#include <chrono>

#include "drivers/setup/can_bus_config.h"
#include "drivers/setup/fault_injection.h"
#include "drivers/sim/sim_drive.h"

// The simulated drive that stands in for the drive of one joint: its node-ID, the identity the
// configuration expects, and a plant with headroom over the axis limits (1.5 x velocity, 3 x
// acceleration) so that it follows what motion plans. Configuration thread.
namespace kerf::drivers {

sim::SimDriveConfig makeSimDriveConfig(const CanBusConfig& config, const CanJoint& joint);

// Injects a fault of the drive itself (every kind but BusOff and ErrorPassive, which belong to
// the bus) into the drive of `joint`.
void injectDriveFault(sim::SimDrive& drive, const CanBusConfig& config, const CanJoint& joint,
                      FaultKind kind, std::chrono::nanoseconds now);

}  // namespace kerf::drivers
