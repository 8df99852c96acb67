#include "drivers/setup/can_drive_stack.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/base/translate.h"
#include "drivers/canopen/cob_id.h"

namespace kerf::drivers {

namespace {

using canopen::BootPlan;
using canopen::MasterErrc;
using canopen::PdoEntry;
using canopen::PdoLayout;

constexpr uint16_t kEmcyErrorPassive = 0x8120;  // CiA 301: CAN in error passive mode

uint32_t countsOf(double value) {
    return static_cast<uint32_t>(std::clamp(std::llround(value), 0LL, 0xFFFFFFFFLL));
}

// 0x60C2: period = value * 10^exponent s with value 1..255.
void interpolationPeriod(std::chrono::nanoseconds period, uint8_t& value, int8_t& exponent) {
    int64_t ns = period.count();
    int64_t unit = 1'000'000;  // 10^-3 s
    for (int8_t e = -3; e >= -6; --e, unit /= 10) {
        if (ns % unit == 0 && ns / unit <= 255) {
            value = static_cast<uint8_t>(ns / unit);
            exponent = e;
            return;
        }
    }
    value = static_cast<uint8_t>(std::clamp<int64_t>(ns / 1000, 1, 255));
    exponent = -6;
}

PdoLayout rpdoLayout(const CanJoint& j) {
    PdoLayout p;
    p.cobId = canopen::rpdoCobId(1, j.node);
    p.transmissionType = 1;
    p.add({0x6040, 0, 16});
    p.add(j.mode == cia402::Mode::CyclicPosition ? PdoEntry{0x607A, 0, 32}
                                                 : PdoEntry{0x60FF, 0, 32});
    return p;
}

PdoLayout tpdoLayout(const CanJoint& j) {
    PdoLayout p;
    p.cobId = canopen::tpdoCobId(1, j.node);
    p.transmissionType = 1;
    p.add({0x6041, 0, 16});
    p.add({0x6064, 0, 32});
    return p;
}

BootPlan bootPlan(const CanBusConfig& c, const CanJoint& j) {
    BootPlan plan;
    // A2.4 step 2: a CiA 402 device of the configured vendor and product.
    plan.expect({0x1000, 0}, 0x0192, 0xFFFF, MasterErrc::DeviceTypeMismatch);
    if (c.vendorId)
        plan.expect({0x1018, 1}, *c.vendorId, 0xFFFFFFFFu, MasterErrc::IdentityMismatch);
    if (c.productCode)
        plan.expect({0x1018, 2}, *c.productCode, 0xFFFFFFFFu, MasterErrc::IdentityMismatch);
    plan.read({0x1018, 3});  // revision, for the record
    // Step 3: the mode must be supported (0x6502 bit = mode - 1).
    uint32_t modeBit = 1u << (static_cast<int>(j.mode) - 1);
    plan.expect({0x6502, 0}, modeBit, modeBit, MasterErrc::ModeNotSupported);
    // Step 4: heartbeats both ways; a lost master quick-stops the drive (0x6007 = 3).
    plan.write({0x1017, 0}, static_cast<uint32_t>(c.heartbeatPeriod.count()), 2);
    plan.write({0x1016, 1},
               canopen::heartbeatConsumerEntry(c.masterNode,
                                               static_cast<uint16_t>(c.heartbeatTimeout.count())),
               4);
    plan.write({0x6007, 0}, 3, 2);
    // Step 5: quick stop ramps with 0x6085 and holds in Quick stop active (0x605A = 6), so an
    // axis carrying a load stays under control.
    plan.write({0x605A, 0}, 6, 2);
    plan.write({0x6085, 0}, countsOf(j.maxAcceleration * j.countsPerUnit), 4);
    if (j.mode == cia402::Mode::CyclicPosition) {
        double cycleMs = std::chrono::duration<double, std::milli>(c.cyclePeriod).count();
        plan.write({0x6065, 0}, countsOf(j.followingErrorWindow * j.countsPerUnit), 4);
        plan.write({0x6066, 0}, static_cast<uint32_t>(std::max(10.0, std::ceil(3.0 * cycleMs))), 2);
    } else if (j.mode == cia402::Mode::ProfileVelocity) {
        plan.write({0x6083, 0}, countsOf(j.maxAcceleration * j.countsPerUnit), 4);
        plan.write({0x6084, 0}, countsOf(j.maxAcceleration * j.countsPerUnit), 4);
    }
    // Step 6: the drive interpolates over one SYNC period.
    uint8_t value = 1;
    int8_t exponent = -3;
    interpolationPeriod(c.cyclePeriod, value, exponent);
    plan.write({0x60C2, 1}, value, 1);
    plan.write({0x60C2, 2}, static_cast<uint8_t>(exponent), 1);
    // Step 7: RPDO1 and TPDO1 synchronous, the others switched off.
    plan.configurePdo(false, 1, rpdoLayout(j));
    for (int n = 2; n <= 4; ++n)
        plan.disablePdo(false, n, canopen::rpdoCobId(n, j.node));
    plan.configurePdo(true, 1, tpdoLayout(j));
    for (int n = 2; n <= 4; ++n)
        plan.disablePdo(true, n, canopen::tpdoCobId(n, j.node));
    // Step 8: the mode, read back.
    plan.write({0x6060, 0}, static_cast<uint8_t>(j.mode), 1);
    plan.expect({0x6061, 0}, static_cast<uint8_t>(j.mode), 0xFF, MasterErrc::ReadBackMismatch);
    return plan;
}

std::string seconds(std::chrono::nanoseconds t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", std::chrono::duration<double>(t).count());
    return text;
}

}  // namespace

canopen::MasterConfig makeMasterConfig(const CanBusConfig& c) {
    canopen::MasterConfig m;
    m.masterNode = c.masterNode;
    m.heartbeatPeriod = c.heartbeatPeriod;
    m.heartbeatTimeout = c.heartbeatTimeout;
    m.cyclePeriod = c.cyclePeriod;
    m.pdoLossCycles = c.pdoLossCycles;
    m.sdoTimeout = c.sdoTimeout;
    for (const CanJoint& j : c.joints) {
        if (j.node == 0) continue;
        canopen::MasterNodeConfig node;
        node.id = j.node;
        node.boot = bootPlan(c, j);
        node.rpdo = rpdoLayout(j);
        node.tpdo = tpdoLayout(j);
        m.nodes.push_back(std::move(node));
    }
    return m;
}

cia402::AdapterConfig makeAdapterConfig(const CanBusConfig& c) {
    cia402::AdapterConfig a;
    a.cyclePeriod = c.cyclePeriod;
    // A node's controller in error passive (EMCY 0x8120) still delivers every frame, so it warns
    // like the master's own: stopping mid-cut would risk tool and part for nothing, and a bus
    // that really loses frames is caught by the PDO check within pdo_loss_cycles.
    a.emcyWarnings = {kEmcyErrorPassive};
    int node = 0;
    for (const CanJoint& j : c.joints) {
        cia402::JointDrive d;
        d.node = j.node != 0 ? node++ : -1;
        d.mode = j.mode;
        d.countsPerUnit = j.countsPerUnit;
        d.followingErrorWindow = j.followingErrorWindow;
        a.joints.push_back(d);
    }
    return a;
}

CanDriveStack::CanDriveStack(const CanBusConfig& config, can::CanChannel& channel)
    : m_config(config),
      m_master(makeMasterConfig(config)),
      m_adapter(m_master, channel, m_clock, makeAdapterConfig(config)) {}

std::string jointName(const CanBusConfig& config, int joint) {
    if (joint < 0 || joint >= static_cast<int>(config.joints.size())) return "bus";
    char axis = config.joints[static_cast<size_t>(joint)].axis;
    return axis == 'S' ? std::string("spindle") : std::string("axis ") + axis;
}

DiagnosticList CanDriveStack::diagnostics() const {
    DiagnosticList list;
    for (size_t i = 0; i < m_adapter.recordCount(); ++i) {
        const cia402::StopRecord& r = m_adapter.record(i);
        bool warning = r.reason == cia402::StopReason::ErrorPassive ||
                       r.reason == cia402::StopReason::EmergencyWarning;
        Diagnostic d;
        d.severity = warning ? Severity::Warning : Severity::Error;
        d.code = warning ? "drives.warning" : "drives.stop";
        if (r.joint < 0) {
            d.messageTemplate = KERF_TR_NOOP("CAN bus: {1} at {2} s");
            d.args = {cia402::describeStop(r), seconds(r.time)};
        } else {
            d.messageTemplate = warning ? KERF_TR_NOOP("CAN node {1} ({2}): {3} at {4} s")
                                        : KERF_TR_NOOP(
                                              "CAN node {1} ({2}): {3} at {4} s; every drive "
                                              "was quick-stopped");
            d.args = {std::to_string(r.node), jointName(m_config, r.joint), cia402::describeStop(r),
                      seconds(r.time)};
        }
        list.push_back(std::move(d));
    }
    return list;
}

}  // namespace kerf::drivers
