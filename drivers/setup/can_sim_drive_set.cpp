#include "drivers/setup/can_sim_drive_set.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/base/translate.h"
#include "drivers/setup/sim_drive_factory.h"
#include "motion/port/motion_status.h"

namespace kerf::drivers {

namespace {

using std::chrono::nanoseconds;

constexpr int kMaxEventsPerPeriod = 100000;  // bounds advance(); far above any real period

nanoseconds toNanoseconds(double seconds) {
    return nanoseconds(std::llround(seconds * 1e9));
}

bool bootFault(FaultKind kind) {
    return kind == FaultKind::SlowBoot || kind == FaultKind::Identity ||
           kind == FaultKind::SdoAbort;
}

}  // namespace

Expected<std::unique_ptr<CanSimDriveSet>> CanSimDriveSet::create(
    const machine::MachineConfig& config, CanSimOptions options) {
    Expected<CanBusConfig> bus = makeCanBusConfig(config);
    if (!bus) return bus.error();
    for (const FaultInjection& f : options.faults) {
        bool known = f.node == 0;
        for (const CanJoint& j : bus->joints)
            known = known || (j.node != 0 && j.node == f.node);
        if (!known) {
            Diagnostic d;
            d.code = "drives.fault-spec";
            d.messageTemplate =
                KERF_TR_NOOP("--inject-fault: node {1} is not a drive of this machine");
            d.args = {std::to_string(f.node)};
            return d;
        }
    }
    std::unique_ptr<CanSimDriveSet> set(
        new CanSimDriveSet(std::move(bus).value(), std::move(options)));
    if (!set->m_options.tracePath.empty()) {
        if (std::error_code error = set->m_trace.open(set->m_options.tracePath)) {
            Diagnostic d;
            d.code = "drives.trace";
            d.messageTemplate = KERF_TR_NOOP("cannot write the CAN trace {1}: {2}");
            d.args = {set->m_options.tracePath.string(), error.message()};
            return d;
        }
        set->m_trace.setLimit(set->m_options.traceLimitBytes);
        set->m_bus.addObserver(set->m_trace);
    }
    return set;
}

CanSimDriveSet::CanSimDriveSet(CanBusConfig config, CanSimOptions options)
    : m_config(std::move(config)),
      m_options(std::move(options)),
      m_bus(m_config.bitrate),
      m_masterChannel(m_bus.attach("master")) {
    for (size_t i = 0; i < m_config.joints.size(); ++i) {
        const CanJoint& j = m_config.joints[i];
        if (j.node == 0) continue;
        Drive d;
        d.channel = &m_bus.attach("node " + std::to_string(j.node));
        d.drive = std::make_unique<sim::SimDrive>(makeSimDriveConfig(m_config, j), *d.channel);
        d.joint = static_cast<int>(i);
        m_drives.push_back(std::move(d));
    }
    m_stack = std::make_unique<CanDriveStack>(m_config, m_masterChannel);
    for (const FaultInjection& f : m_options.faults) {
        if (!bootFault(f.kind)) m_timedFaults.push_back(f);
    }
    std::stable_sort(
        m_timedFaults.begin(), m_timedFaults.end(),
        [](const FaultInjection& a, const FaultInjection& b) { return a.timeS < b.timeS; });
}

CanSimDriveSet::~CanSimDriveSet() = default;

CanSimDriveSet::Drive* CanSimDriveSet::driveOf(uint8_t node) noexcept {
    for (Drive& d : m_drives) {
        if (d.drive->node() == node) return &d;
    }
    return nullptr;
}

sim::SimDrive* CanSimDriveSet::driveForNode(uint8_t node) noexcept {
    Drive* d = driveOf(node);
    return d ? d->drive.get() : nullptr;
}

void CanSimDriveSet::setInitialPositions(std::span<const double> joints) {
    for (Drive& d : m_drives) {
        auto j = static_cast<size_t>(d.joint);
        if (j < joints.size())
            d.drive->setInitialPosition(joints[j] * m_config.joints[j].countsPerUnit);
    }
}

void CanSimDriveSet::applyFault(const FaultInjection& f) noexcept {
    if (f.node == 0) {
        m_bus.setState(m_masterChannel, f.kind == FaultKind::BusOff
                                            ? can::ControllerState::BusOff
                                            : can::ControllerState::ErrorPassive);
        return;
    }
    Drive* d = driveOf(f.node);
    if (!d) return;
    switch (f.kind) {
        case FaultKind::BusOff:
            m_bus.setState(*d->channel, can::ControllerState::BusOff);
            break;
        case FaultKind::ErrorPassive:
            m_bus.setState(*d->channel, can::ControllerState::ErrorPassive);
            break;
        default:
            injectDriveFault(*d->drive, m_config, m_config.joints[static_cast<size_t>(d->joint)],
                             f.kind, m_now);
            break;
    }
}

MaybeError CanSimDriveSet::boot() {
    for (const FaultInjection& f : m_options.faults) {
        if (bootFault(f.kind)) applyFault(f);
    }
    motion::DriveBus& bus = m_stack->bus();
    bus.request(motion::DriveRequest::Enable);
    for (Drive& d : m_drives)
        d.drive->powerOn(m_now);
    m_stack->clock().set(m_now);
    m_stack->start();
    std::array<motion::JointFeedback, motion::kMaxJoints> feedback{};
    std::array<motion::JointSetpoint, motion::kMaxJoints> setpoints{};
    auto joints = static_cast<size_t>(bus.jointCount());
    double periodS = std::chrono::duration<double>(m_config.servoPeriod).count();
    nanoseconds deadline = m_now + toNanoseconds(m_options.bootTimeoutS);
    while (m_now < deadline) {
        bus.read({feedback.data(), joints});
        if (m_stack->adapter().allEnabled()) return std::nullopt;
        if (stopped()) {
            DiagnosticList d = diagnostics();
            return d.front();
        }
        for (size_t j = 0; j < joints; ++j)
            setpoints[j].position = feedback[j].position;
        bus.write({setpoints.data(), joints});
        advance(periodS);
    }
    std::string waiting;
    const canopen::Master& master = m_stack->master();
    for (size_t i = 0; i < master.nodeCount(); ++i) {
        if (!waiting.empty()) waiting += ", ";
        waiting += "node " + std::to_string(master.nodeId(i)) + " " +
                   canopen::nodePhaseName(master.phase(i)) + " (" +
                   cia402::stateName(m_stack->adapter().axis(static_cast<int>(i)).state()) + ")";
    }
    Diagnostic d;
    d.code = "drives.boot-timeout";
    d.messageTemplate = KERF_TR_NOOP("the CAN drives were not enabled within {1} s: {2}");
    d.args = {std::to_string(m_options.bootTimeoutS), waiting};
    return d;
}

void CanSimDriveSet::advance(double periodS) noexcept {
    nanoseconds until = m_now + toNanoseconds(periodS);
    for (int guard = 0; guard < kMaxEventsPerPeriod; ++guard) {
        // The next event: a frame's transmission ends, a drive's timer, an injected fault.
        nanoseconds t = until;
        if (std::optional<nanoseconds> delivery = m_bus.nextDelivery()) {
            t = std::min(t, std::max(*delivery, m_now));
        }
        for (const Drive& d : m_drives) {
            nanoseconds deadline = d.drive->nextDeadline();
            if (deadline > m_now) t = std::min(t, deadline);
        }
        if (m_nextFault < m_timedFaults.size()) {
            nanoseconds faultTime = toNanoseconds(m_timedFaults[m_nextFault].timeS);
            if (faultTime > m_now) t = std::min(t, faultTime);
        }
        m_bus.advanceTo(t);
        m_now = t;
        while (m_nextFault < m_timedFaults.size() &&
               toNanoseconds(m_timedFaults[m_nextFault].timeS) <= m_now) {
            applyFault(m_timedFaults[m_nextFault++]);
        }
        for (Drive& d : m_drives)
            d.drive->poll(m_now);
        if (m_now >= until) break;
    }
    m_stack->clock().set(m_now);
}

DiagnosticList CanSimDriveSet::diagnostics() const {
    DiagnosticList list = m_stack->diagnostics();
    if (m_traceError) list.push_back(*m_traceError);
    if (m_trace.truncated()) {
        Diagnostic d;
        d.severity = Severity::Warning;
        d.code = "drives.trace-limit";
        d.messageTemplate = KERF_TR_NOOP(
            "the CAN trace {1} stops at its limit of {2} bytes; the rest of the run is not in it");
        d.args = {m_options.tracePath.string(), std::to_string(m_options.traceLimitBytes)};
        list.push_back(d);
    }
    return list;
}

double CanSimDriveSet::measuredBusLoad() const noexcept {
    if (m_now.count() <= 0) return 0.0;
    return std::chrono::duration<double>(m_bus.busyTime()).count() /
           std::chrono::duration<double>(m_now).count();
}

MaybeError CanSimDriveSet::finish() {
    if (!m_trace.isOpen()) return std::nullopt;
    if (std::error_code error = m_trace.close()) {
        Diagnostic d;
        d.code = "drives.trace";
        d.messageTemplate = KERF_TR_NOOP("cannot write the CAN trace {1}: {2}");
        d.args = {m_options.tracePath.string(), error.message()};
        m_traceError = d;
        return d;
    }
    return std::nullopt;
}

}  // namespace kerf::drivers
