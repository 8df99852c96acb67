#include "drivers/setup/can_bus_config.h"

#include <cmath>
#include <cstdio>

#include "core/base/translate.h"
#include "core/machine/machine_validation.h"
#include "drivers/can/bit_timing.h"

namespace kerf::drivers {

namespace {

constexpr uint8_t kPdoBytes = 6;  // controlword + INT32 target, statusword + INT32 actual

Diagnostic configError(std::string code, std::string messageTemplate,
                       std::vector<std::string> args) {
    Diagnostic d;
    d.severity = Severity::Error;
    d.code = std::move(code);
    d.messageTemplate = std::move(messageTemplate);
    d.args = std::move(args);
    return d;
}

std::string percent(double share) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f", share * 100.0);
    return text;
}

std::string milliseconds(std::chrono::nanoseconds t) {
    char text[16];
    std::snprintf(text, sizeof text, "%g", std::chrono::duration<double, std::milli>(t).count());
    return text;
}

}  // namespace

int CanBusConfig::nodeCount() const noexcept {
    int count = 0;
    for (const CanJoint& j : joints)
        count += j.node != 0 ? 1 : 0;
    return count;
}

canopen::BusLoad canBusLoad(int nodes, uint32_t bitrate, std::chrono::nanoseconds cycle,
                            std::chrono::milliseconds heartbeatPeriod) {
    std::vector<uint8_t> pdos(static_cast<size_t>(2 * nodes), kPdoBytes);
    return canopen::estimateBusLoad(bitrate, cycle, pdos, nodes + 1, heartbeatPeriod);
}

std::string describeBusLoad(int nodes, uint32_t bitrate, std::chrono::nanoseconds cycle,
                            const canopen::BusLoad& load) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "%d nodes, %u kbit/s, %s ms cycle: %u-%u of %u bit times per cycle, %s-%s %% "
                  "(worst case %s %% with heartbeats)",
                  nodes, bitrate / 1000u, milliseconds(cycle).c_str(), load.cycleBitsMin,
                  load.cycleBitsMax, load.cycleBitTimes, percent(load.minimum).c_str(),
                  percent(static_cast<double>(load.cycleBitsMax) / load.cycleBitTimes).c_str(),
                  percent(load.worstCase).c_str());
    return text;
}

Expected<CanBusConfig> makeCanBusConfig(const machine::MachineConfig& config) {
    const machine::DrivesConfig& d = config.drives;
    CanBusConfig bus;
    bus.interface = d.interface;
    bus.bitrate = static_cast<uint32_t>(d.bitrate);
    bus.servoPeriod = std::chrono::nanoseconds(std::llround(config.servoPeriodMs * 1e6));
    bus.cyclePeriod = std::chrono::nanoseconds(std::llround(d.cyclePeriodMs * 1e6));
    bus.masterNode = static_cast<uint8_t>(d.masterNode);
    bus.heartbeatPeriod = std::chrono::milliseconds(d.heartbeatPeriodMs);
    bus.heartbeatTimeout = std::chrono::milliseconds(d.heartbeatTimeoutMs);
    bus.pdoLossCycles = d.pdoLossCycles;
    if (!d.vendorId.empty()) bus.vendorId = machine::parseDriveIdentity(d.vendorId);
    if (!d.productCode.empty()) bus.productCode = machine::parseDriveIdentity(d.productCode);
    // motion's joints: the enabled axes in axis order (the config keeps them so), then the spindle.
    for (const machine::AxisConfig& axis : config.axes) {
        if (!axis.enabled) continue;
        if (axis.driveNode == 0) {
            return configError("drives.config",
                               KERF_TR_NOOP("axes.{1}.drive_node is 0: every enabled axis needs a "
                                            "CANopen drive on the drive bus"),
                               {std::string(1, axis.letter)});
        }
        CanJoint j;
        j.axis = axis.letter;
        j.node = static_cast<uint8_t>(axis.driveNode);
        j.rotary = axis.type == machine::AxisType::Rotary;
        j.countsPerUnit = axis.driveCountsPerUnit;
        j.followingErrorWindow = axis.followingErrorWindow;
        j.maxVelocity = axis.maxVelocityPerS;
        j.maxAcceleration = axis.maxAccelerationPerS2;
        bus.joints.push_back(j);
    }
    CanJoint spindle;
    spindle.axis = 'S';
    spindle.node = static_cast<uint8_t>(config.spindle.driveNode);
    spindle.mode = config.spindle.driveMode == machine::SpindleDriveMode::Pv
                       ? cia402::Mode::ProfileVelocity
                       : cia402::Mode::CyclicVelocity;
    spindle.rotary = true;
    spindle.countsPerUnit = config.spindle.driveCountsPerDeg;
    spindle.maxVelocity = config.spindle.maxRpm * 6.0;  // deg/s
    spindle.maxAcceleration = spindle.maxVelocity;      // full speed to standstill in 1 s
    bus.joints.push_back(spindle);

    int nodes = bus.nodeCount();
    bus.load = canBusLoad(nodes, bus.bitrate, bus.cyclePeriod, bus.heartbeatPeriod);
    if (!bus.load.acceptable()) {
        return configError(
            "drives.bus-load",
            KERF_TR_NOOP(
                "CAN bus load {1} % is above the 80 % limit ({2}); lengthen "
                "drives.cycle_period, raise drives.bitrate or split the drives over two buses"),
            {percent(bus.load.worstCase),
             describeBusLoad(nodes, bus.bitrate, bus.cyclePeriod, bus.load)});
    }
    return bus;
}

}  // namespace kerf::drivers
