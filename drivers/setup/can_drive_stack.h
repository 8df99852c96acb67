#pragma once

#include "core/base/diagnostic.h"
#include "drivers/can/can_channel.h"
#include "drivers/canopen/master.h"
#include "drivers/canopen/protocol_clock.h"
#include "drivers/cia402/drive_bus_adapter.h"
#include "drivers/setup/can_bus_config.h"

// The master side of a CANopen drive bus, wired from a CanBusConfig over any CAN channel (the
// virtual bus, SocketCAN, the UDP bus): the CiA 402 boot plan of every drive (A2.4: identity,
// heartbeats, quick stop 0x605A = 6, following-error window, interpolation period, PDO mapping,
// mode), the master and the DriveBus adapter. The owner sets clock() and runs bus() from the
// servo cycle's thread; construction, start() and diagnostics() are for a normal thread.
namespace kerf::drivers {

canopen::MasterConfig makeMasterConfig(const CanBusConfig& config);
cia402::AdapterConfig makeAdapterConfig(const CanBusConfig& config);

class CanDriveStack {
public:
    CanDriveStack(const CanBusConfig& config, can::CanChannel& channel);

    canopen::ProtocolClock& clock() noexcept { return m_clock; }
    canopen::Master& master() noexcept { return m_master; }
    cia402::DriveBusAdapter& adapter() noexcept { return m_adapter; }
    motion::DriveBus& bus() noexcept { return m_adapter; }
    const CanBusConfig& config() const noexcept { return m_config; }

    // Starts booting every drive at clock().now(); motion's Enable request enables them once
    // they are operational.
    void start() noexcept { m_master.start(m_clock.now()); }

    // Stops and warnings so far, each naming the node, its axis and the reason.
    DiagnosticList diagnostics() const;

private:
    CanBusConfig m_config;
    canopen::ProtocolClock m_clock;
    canopen::Master m_master;
    cia402::DriveBusAdapter m_adapter;
};

// "axis X", "spindle": the joint a record names, for messages.
std::string jointName(const CanBusConfig& config, int joint);

}  // namespace kerf::drivers
