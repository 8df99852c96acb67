#include "drivers/cia402/drive_bus_adapter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "drivers/canopen/master_error.h"
#include "drivers/canopen/pdo.h"

namespace kerf::drivers::cia402 {

namespace {

using std::chrono::nanoseconds;

constexpr int kMaxFramesPerRead = 512;  // bounds the receive loop

// CiA 301 codes for what the master detects itself.
constexpr uint16_t kHeartbeatErrorCode = 0x8130;  // life guard or heartbeat error
constexpr uint16_t kPdoTimeoutCode = 0x8250;      // (R)PDO timeout, from the master's side
constexpr uint16_t kCommunicationCode = 0x8100;   // communication, generic
constexpr uint16_t kFollowingErrorCode = 0x8611;

int32_t toCounts(double value) noexcept {
    double rounded = std::nearbyint(value);
    // Positions wrap like the drive's INT32 position actual does.
    auto wide = static_cast<int64_t>(std::clamp(rounded, -9.0e18, 9.0e18));
    return static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(wide)));
}

// Distance of two INT32 positions that may have wrapped.
int64_t countsApart(int32_t a, int32_t b) noexcept {
    auto difference = static_cast<int32_t>(static_cast<uint32_t>(a) - static_cast<uint32_t>(b));
    return std::abs(static_cast<int64_t>(difference));
}

// States in which a drive no longer drives the axis on: a finished quick stop, a finished
// fault reaction, or the power stage off.
bool stopFinished(const DriveAxis& axis) noexcept {
    switch (axis.state()) {
        case State::QuickStopActive:
            return (axis.statusword() & kStatusTargetReached) != 0;
        case State::FaultReactionActive:
            return false;
        default:
            return true;
    }
}

}  // namespace

DriveBusAdapter::DriveBusAdapter(canopen::Master& master, can::CanChannel& channel,
                                 const canopen::ProtocolClock& clock, AdapterConfig config)
    : m_master(master), m_channel(channel), m_clock(clock), m_config(std::move(config)) {
    m_jointOfNode.fill(-1);
    m_joints.resize(m_config.joints.size());
    for (size_t i = 0; i < m_joints.size(); ++i) {
        Joint& j = m_joints[i];
        j.config = m_config.joints[i];
        j.axis.configure(j.config.mode, m_config.enableStepTimeout);
        if (j.config.node >= 0)
            m_jointOfNode[static_cast<size_t>(j.config.node)] = static_cast<int>(i);
    }
}

int DriveBusAdapter::jointOfNode(size_t nodeIndex) const noexcept {
    return nodeIndex < m_jointOfNode.size() ? m_jointOfNode[nodeIndex] : -1;
}

double DriveBusAdapter::position(int joint) const noexcept {
    const Joint& j = m_joints[static_cast<size_t>(joint)];
    if (j.config.node < 0) return j.setpoint;
    return static_cast<double>(j.counts) / j.config.countsPerUnit + j.offset;
}

Standstill DriveBusAdapter::standstill(int joint) const noexcept {
    const Joint& j = m_joints[static_cast<size_t>(joint)];
    if (j.config.node < 0) return Standstill::AtRest;  // nothing moves it once motion stops
    // The master calls a node lost after pdoLossCycles without TPDO; one more and it is silent.
    auto silentAfter = m_config.cyclePeriod * (m_master.config().pdoLossCycles + 1);
    if (!j.haveCounts || m_clock.now() - j.lastTpdo > silentAfter) return Standstill::Unknown;
    return stopFinished(j.axis) && j.stillTpdos >= kRestTpdos ? Standstill::AtRest
                                                              : Standstill::Moving;
}

bool DriveBusAdapter::allEnabled() const noexcept {
    if (m_stopped) return false;
    for (const Joint& j : m_joints) {
        if (j.config.node >= 0 && !(j.handedOver && j.axis.followsTarget())) return false;
    }
    return true;
}

StopRecord DriveBusAdapter::recordFor(StopReason reason, int joint,
                                      nanoseconds now) const noexcept {
    StopRecord r;
    r.reason = reason;
    r.joint = joint;
    r.time = now;
    if (joint >= 0) {
        const Joint& j = m_joints[static_cast<size_t>(joint)];
        r.node = j.config.node >= 0 ? m_master.nodeId(static_cast<size_t>(j.config.node)) : 0;
        r.state = j.axis.state();
    }
    return r;
}

void DriveBusAdapter::stop(StopRecord record, bool warningOnly) noexcept {
    if (record.joint >= 0 && !warningOnly) {
        Joint& j = m_joints[static_cast<size_t>(record.joint)];
        if (j.faulted) return;  // one record per joint and stop
        j.faulted = true;
        j.faultCode = record.code;
    }
    if (m_recordCount < m_records.size()) m_records[m_recordCount++] = record;
    if (!warningOnly && !m_stopped) {
        m_stopped = true;
        m_newStop = true;
    }
}

void DriveBusAdapter::quickStopAll(nanoseconds now) noexcept {
    for (Joint& j : m_joints) {
        j.axis.setGoal(Goal::QuickStop, now);
        if (j.config.node < 0) continue;
        if (j.config.mode != Mode::CyclicPosition) j.target = 0;  // velocity modes: stop
        packRpdo(j);
        m_master.sendRpdoNow(static_cast<size_t>(j.config.node));
    }
}

void DriveBusAdapter::receive(nanoseconds now) noexcept {
    can::CanFrame frame;
    for (int n = 0; n < kMaxFramesPerRead && m_channel.receive(frame); ++n)
        m_master.onFrame(frame, now);
}

void DriveBusAdapter::handleEvents(nanoseconds now) noexcept {
    canopen::MasterEvent e;
    while (m_master.popEvent(e)) {
        int joint = jointOfNode(e.nodeIndex);
        StopRecord r = recordFor(StopReason::DriveFault, joint, now);
        r.node = e.node;
        r.error = e.error;
        switch (e.kind) {
            case canopen::MasterEventKind::Configured:
                break;
            case canopen::MasterEventKind::Operational:
                if (joint >= 0) m_joints[static_cast<size_t>(joint)].axis.restartTimer(now);
                break;
            case canopen::MasterEventKind::BootFailed:
                r.reason = StopReason::BootFailed;
                r.object = e.object;
                r.code = kCommunicationCode;
                stop(r);
                break;
            case canopen::MasterEventKind::HeartbeatLost:
                r.reason = StopReason::HeartbeatLost;
                r.code = kHeartbeatErrorCode;
                stop(r);
                break;
            case canopen::MasterEventKind::UnexpectedState:
                r.reason = StopReason::UnexpectedNmtState;
                r.nmtState = e.state;
                r.code = kCommunicationCode;
                stop(r);
                break;
            case canopen::MasterEventKind::PdoMissing:
                r.reason = StopReason::PdoMissing;
                r.code = kPdoTimeoutCode;
                stop(r);
                break;
            case canopen::MasterEventKind::Emergency: {
                if (e.emcy.code == 0) break;  // error reset
                r.reason = StopReason::Emergency;
                r.code = e.emcy.code;
                r.errorRegister = e.emcy.errorRegister;
                if (joint >= 0) {
                    m_joints[static_cast<size_t>(joint)].emcyCode = e.emcy.code;
                    m_joints[static_cast<size_t>(joint)].emcyRegister = e.emcy.errorRegister;
                }
                canopen::NodePhase phase = m_master.phase(e.nodeIndex);
                bool started = phase == canopen::NodePhase::Starting ||
                               phase == canopen::NodePhase::Operational;
                bool whitelisted =
                    std::find(m_config.emcyWarnings.begin(), m_config.emcyWarnings.end(),
                              e.emcy.code) != m_config.emcyWarnings.end();
                if (!started || whitelisted) {
                    r.reason = StopReason::EmergencyWarning;
                    stop(r, true);
                } else {
                    stop(r);
                }
                break;
            }
        }
    }
}

void DriveBusAdapter::supervise(Joint& j, int index, nanoseconds now) noexcept {
    const canopen::TpdoSlot& slot = m_master.tpdo(static_cast<size_t>(j.config.node));
    if (slot.sequence == j.sequence) {
        // The step timer runs once the node is operational (restarted by that event).
        bool operational =
            m_master.phase(static_cast<size_t>(j.config.node)) == canopen::NodePhase::Operational;
        if (operational && !j.faulted && j.axis.stepTimedOut(now)) {
            stop(recordFor(StopReason::EnableTimeout, index, now));
        }
        return;
    }
    j.sequence = slot.sequence;
    j.expectTpdo = false;
    std::span<const uint8_t> data(slot.data.data(), slot.length);
    auto statusword = static_cast<uint16_t>(
        canopen::unpackField(data, static_cast<size_t>(j.config.tpdoStatusword), 2));
    auto raw = static_cast<int32_t>(
        canopen::unpackField(data, static_cast<size_t>(j.config.tpdoPosition), 4));
    // Unwrap the INT32 position: the difference of two samples is taken modulo 2^32.
    j.counts = j.haveCounts ? j.counts + static_cast<int32_t>(static_cast<uint32_t>(raw) -
                                                              static_cast<uint32_t>(j.raw))
                            : raw;
    j.raw = raw;
    j.haveCounts = true;
    j.lastTpdo = now;
    if (countsApart(raw, j.restRaw) <= 1) {
        ++j.stillTpdos;
    } else {
        j.restRaw = raw;
        j.stillTpdos = 0;
    }
    j.axis.onStatusword(statusword, now);

    State state = j.axis.state();
    if (j.faulted) {
        j.following = false;
        return;
    }
    StopRecord r = recordFor(StopReason::DriveFault, index, now);
    if (state == State::Fault || state == State::FaultReactionActive) {
        r.code = j.emcyCode;
        r.errorRegister = j.emcyRegister;
        stop(r);
    } else if (j.following && state != State::OperationEnabled && j.axis.goal() == Goal::Enabled) {
        r.reason = StopReason::UnexpectedState;
        stop(r);
    } else if (j.following && state == State::OperationEnabled && !j.axis.followsTarget()) {
        r.reason = StopReason::TargetIgnored;
        stop(r);
    } else if (j.axis.followingError()) {
        r.reason = StopReason::FollowingError;
        r.code = kFollowingErrorCode;
        stop(r);
    } else if (j.config.mode == Mode::CyclicPosition && j.handedOver &&
               j.config.followingErrorWindow > 0.0) {
        // The RPDO goes out just before its SYNC: target k is applied at SYNC k and reached at
        // SYNC k + 1, whose position this TPDO (after SYNC syncs - 1) reports.
        uint64_t syncs = m_master.syncCount();
        if (syncs >= j.handedOverAt + 2) {
            int32_t expected = j.targets[(syncs - 2) % j.targets.size()];
            double error = std::fabs(static_cast<double>(static_cast<int32_t>(
                               static_cast<uint32_t>(raw) - static_cast<uint32_t>(expected)))) /
                           j.config.countsPerUnit;
            if (error > 2.0 * j.config.followingErrorWindow) {
                r.reason = StopReason::FollowingError;
                r.code = kFollowingErrorCode;
                r.value = error;
                stop(r);
            }
        }
    }
    j.following = j.axis.followsTarget() && j.handedOver;
}

motion::BusResult DriveBusAdapter::read(std::span<motion::JointFeedback> feedback) noexcept {
    nanoseconds now = m_clock.now();
    receive(now);
    m_master.advance(now);
    handleEvents(now);
    can::ControllerState controller = m_channel.state();
    if (controller == can::ControllerState::BusOff || controller == can::ControllerState::Stopped) {
        if (!m_busOff) stop(recordFor(StopReason::BusOff, -1, now));
        m_busOff = true;
    } else if (controller == can::ControllerState::ErrorPassive && !m_errorPassiveSeen) {
        m_errorPassiveSeen = true;
        stop(recordFor(StopReason::ErrorPassive, -1, now), true);
    }
    bool late = false;
    for (size_t i = 0; i < m_joints.size(); ++i) {
        Joint& j = m_joints[i];
        if (j.config.node < 0) continue;
        supervise(j, static_cast<int>(i), now);
        late = late || j.expectTpdo;
    }
    if (m_newStop) {
        m_newStop = false;
        quickStopAll(now);
    }
    // Motion skips write() while it is in fault: the bus keeps its rhythm (SYNC, quick stop).
    if (!m_wroteSinceRead) runCommunicationCycle(now);
    m_wroteSinceRead = false;
    flush();

    for (size_t i = 0; i < m_joints.size() && i < feedback.size(); ++i) {
        const Joint& j = m_joints[i];
        motion::JointFeedback& fb = feedback[i];
        fb.position = position(static_cast<int>(i));
        fb.homeSwitch = false;
        fb.probeLatched = false;
        fb.faultCode = j.faulted ? j.faultCode : 0;
        if (j.faulted || m_busOff) {
            fb.state = motion::DriveState::Fault;
            continue;
        }
        if (j.config.node < 0) {
            fb.state = j.axis.goal() == Goal::Enabled     ? motion::DriveState::Enabled
                       : j.axis.goal() == Goal::QuickStop ? motion::DriveState::QuickStop
                                                          : motion::DriveState::Disabled;
            continue;
        }
        switch (j.axis.state()) {
            case State::OperationEnabled:
                fb.state = j.handedOver && j.axis.followsTarget() ? motion::DriveState::Enabled
                                                                  : motion::DriveState::Enabling;
                break;
            case State::QuickStopActive:
                fb.state = motion::DriveState::QuickStop;
                break;
            case State::Fault:
            case State::FaultReactionActive:
                fb.state = motion::DriveState::Fault;
                break;
            default:
                fb.state = j.axis.goal() == Goal::Enabled ? motion::DriveState::Enabling
                                                          : motion::DriveState::Disabled;
                break;
        }
    }
    if (m_busOff) return motion::BusResult::Error;
    return late ? motion::BusResult::Late : motion::BusResult::Ok;
}

void DriveBusAdapter::packRpdo(Joint& j) noexcept {
    std::span<uint8_t> rpdo = m_master.rpdo(static_cast<size_t>(j.config.node));
    canopen::packField(rpdo, static_cast<size_t>(j.config.rpdoControlword), 2,
                       j.axis.nextControlword());
    canopen::packField(rpdo, static_cast<size_t>(j.config.rpdoTarget), 4,
                       static_cast<uint32_t>(j.target));
}

void DriveBusAdapter::runCommunicationCycle(nanoseconds now) noexcept {
    if (!m_master.cycleDue(now)) return;
    double cycleS = std::chrono::duration<double>(m_config.cyclePeriod).count();
    uint64_t sync = m_master.syncCount();  // number of the SYNC this cycle sends
    for (size_t i = 0; i < m_joints.size(); ++i) {
        Joint& j = m_joints[i];
        if (j.config.node < 0) continue;
        bool isPosition = j.config.mode == Mode::CyclicPosition;
        // The target follows the setpoint only while the drive follows it and is meant to.
        if (!j.axis.followsTarget() || j.axis.goal() != Goal::Enabled) j.handedOver = false;
        if (!m_stopped && j.axis.followsTarget() && !j.handedOver && j.haveCounts &&
            j.axis.goal() == Goal::Enabled) {
            // Hand over from holding the actual position to the setpoint only if they agree:
            // otherwise the axis would jump.
            double gap = std::fabs(j.setpoint - position(static_cast<int>(i)));
            if (isPosition && j.config.followingErrorWindow > 0.0 &&
                gap > j.config.followingErrorWindow) {
                StopRecord r = recordFor(StopReason::SetpointJump, static_cast<int>(i), now);
                r.value = gap;
                stop(r);
            } else {
                j.handedOver = true;
                j.handedOverAt = sync;
                j.sentSetpoint = j.setpoint;
            }
        }
        bool live = j.handedOver && !m_stopped && j.axis.followsTarget();
        if (isPosition) {
            if (live) {
                j.target = toCounts((j.setpoint - j.offset) * j.config.countsPerUnit);
            } else if (!j.handedOver && j.haveCounts) {
                j.target = j.raw;  // hold the actual position
            }
        } else {
            double velocity = live ? (j.setpoint - j.sentSetpoint) / cycleS : 0.0;
            j.target = toCounts(velocity * j.config.countsPerUnit);
        }
        j.sentSetpoint = j.setpoint;
        j.targets[sync % j.targets.size()] = j.target;
        packRpdo(j);
        canopen::NodePhase phase = m_master.phase(static_cast<size_t>(j.config.node));
        j.expectTpdo =
            phase == canopen::NodePhase::Operational || phase == canopen::NodePhase::Starting;
    }
    m_master.produceCycle(now);
    // A TPDO found missing while producing the SYNC stops the set in this cycle.
    handleEvents(now);
    if (m_newStop) {
        m_newStop = false;
        quickStopAll(now);
    }
}

motion::BusResult DriveBusAdapter::write(
    std::span<const motion::JointSetpoint> setpoints) noexcept {
    for (size_t i = 0; i < m_joints.size() && i < setpoints.size(); ++i)
        m_joints[i].setpoint = setpoints[i].position;
    m_wroteSinceRead = true;
    runCommunicationCycle(m_clock.now());
    flush();
    return m_busOff ? motion::BusResult::Error : motion::BusResult::Ok;
}

void DriveBusAdapter::flush() noexcept {
    canopen::FrameOutbox& out = m_master.outbox();
    while (!out.empty()) {
        if (m_channel.send(out.front())) ++m_sendErrors;
        out.pop();
    }
}

void DriveBusAdapter::request(motion::DriveRequest request) noexcept {
    nanoseconds now = m_clock.now();
    switch (request) {
        case motion::DriveRequest::Enable:
            if (m_stopped) break;  // a stop needs FaultReset first
            for (Joint& j : m_joints)
                j.axis.setGoal(Goal::Enabled, now);
            break;
        case motion::DriveRequest::Disable:
            for (Joint& j : m_joints) {
                j.axis.setGoal(m_stopped ? Goal::QuickStop : Goal::Disabled, now);
                j.handedOver = false;
            }
            break;
        case motion::DriveRequest::QuickStop:
            for (Joint& j : m_joints)
                j.axis.setGoal(Goal::QuickStop, now);
            break;
        case motion::DriveRequest::FaultReset:
            for (size_t i = 0; i < m_joints.size(); ++i) {
                Joint& j = m_joints[i];
                j.faulted = false;
                j.faultCode = 0;
                j.emcyCode = 0;
                j.handedOver = false;
                j.following = false;
                j.axis.setGoal(Goal::Disabled, now);
                j.axis.requestFaultReset();
                if (j.config.node < 0) continue;
                auto node = static_cast<size_t>(j.config.node);
                canopen::NodePhase phase = m_master.phase(node);
                if (phase == canopen::NodePhase::Lost || phase == canopen::NodePhase::Failed) {
                    m_master.restartNode(node, now);
                }
            }
            m_stopped = false;
            m_newStop = false;
            m_busOff = false;
            break;
    }
}

void DriveBusAdapter::setPosition(int joint, double position) noexcept {
    if (joint < 0 || joint >= jointCount()) return;
    Joint& j = m_joints[static_cast<size_t>(joint)];
    if (j.config.node < 0) {
        j.setpoint = position;
        return;
    }
    double actual = static_cast<double>(j.counts) / j.config.countsPerUnit;
    double shift = position - (actual + j.offset);
    j.offset += shift;
    j.setpoint += shift;
    j.sentSetpoint += shift;
}

void DriveBusAdapter::armProbe(bool) noexcept {
    // The drives' touch probe (0x60B8-0x60BA) is not mapped: probing needs the simulated drives
    // of motion for now, and motion sees no latch from this bus.
}

}  // namespace kerf::drivers::cia402
