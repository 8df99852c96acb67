#pragma once

#include <system_error>
#include <vector>

#include "drivers/can/socketcan_channel.h"
#include "drivers/setup/can_bus_config.h"

// The drive bus on a machine with kernel CAN: the configured SocketCAN interface, filtered to
// what the master consumes (heartbeats/boot-up, EMCY, TPDO1 and SDO responses of its nodes),
// checked against drives.bitrate where the driver reports its bit timing (vcan does not).
// Configuration thread; the channel then serves a CanDriveStack.
namespace kerf::drivers {

std::vector<can::CanFilter> driveBusFilters(const CanBusConfig& config);

// Errors: those of SocketCanChannel::open, or CanErrc::BitrateMismatch.
std::error_code openDriveBus(const CanBusConfig& config, can::SocketCanChannel& channel);

}  // namespace kerf::drivers
