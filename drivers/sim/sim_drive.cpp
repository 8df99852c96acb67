#include "drivers/sim/sim_drive.h"

#include <algorithm>
#include <cmath>

#include "drivers/canopen/boot_plan.h"
#include "drivers/canopen/cob_id.h"
#include "drivers/canopen/emcy.h"
#include "drivers/canopen/pdo.h"
#include "drivers/canopen/sdo_abort.h"

namespace kerf::drivers::sim {

namespace {

using canopen::NmtState;
using canopen::SdoAbort;
using cia402::State;
using std::chrono::nanoseconds;

constexpr uint32_t abortCode(SdoAbort a) noexcept {
    return static_cast<uint32_t>(a);
}

// Objects of CiA 301 / 402 the drive uses by name.
constexpr ObjectAddress kErrorRegister{0x1001, 0};
constexpr ObjectAddress kConsumerHeartbeat{0x1016, 1};
constexpr ObjectAddress kProducerHeartbeat{0x1017, 0};
constexpr ObjectAddress kErrorCode{0x603F, 0};
constexpr ObjectAddress kAbortConnection{0x6007, 0};
constexpr ObjectAddress kControlword{0x6040, 0};
constexpr ObjectAddress kStatusword{0x6041, 0};
constexpr ObjectAddress kQuickStopOption{0x605A, 0};
constexpr ObjectAddress kModes{0x6060, 0};
constexpr ObjectAddress kModesDisplay{0x6061, 0};
constexpr ObjectAddress kPositionActual{0x6064, 0};
constexpr ObjectAddress kFollowingErrorWindow{0x6065, 0};
constexpr ObjectAddress kFollowingErrorTimeout{0x6066, 0};
constexpr ObjectAddress kVelocityActual{0x606C, 0};
constexpr ObjectAddress kTorqueActual{0x6077, 0};
constexpr ObjectAddress kTargetPosition{0x607A, 0};
constexpr ObjectAddress kLimitMin{0x607D, 1};
constexpr ObjectAddress kLimitMax{0x607D, 2};
constexpr ObjectAddress kProfileAccel{0x6083, 0};
constexpr ObjectAddress kProfileDecel{0x6084, 0};
constexpr ObjectAddress kQuickStopDecel{0x6085, 0};
constexpr ObjectAddress kInterpolationValue{0x60C2, 1};
constexpr ObjectAddress kInterpolationExponent{0x60C2, 2};
constexpr ObjectAddress kFollowingErrorActual{0x60F4, 0};
constexpr ObjectAddress kTargetVelocity{0x60FF, 0};
constexpr ObjectAddress kSupportedModes{0x6502, 0};

constexpr uint16_t kEmcyFollowingError = 0x8611;
constexpr uint16_t kEmcyEncoder = 0x7305;
constexpr uint16_t kEmcyHeartbeat = 0x8130;
constexpr uint16_t kEmcyErrorPassive = 0x8120;
constexpr int8_t kModeProfileVelocity = 3;
constexpr int8_t kModeCsp = 8;
constexpr int8_t kModeCsv = 9;

int32_t wrap32(double counts) noexcept {
    auto wide = static_cast<int64_t>(std::clamp(std::nearbyint(counts), -9.0e18, 9.0e18));
    return static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(wide)));
}

uint32_t bytesValue(std::span<const uint8_t> bytes) noexcept {
    uint32_t v = 0;
    for (size_t i = std::min<size_t>(bytes.size(), 4); i > 0; --i)
        v = v << 8 | bytes[i - 1];
    return v;
}

bool isPdoCommunication(uint16_t index) noexcept {
    return (index >= 0x1400 && index < 0x1404) || (index >= 0x1800 && index < 0x1804);
}

bool isPdoMapping(uint16_t index) noexcept {
    return (index >= 0x1600 && index < 0x1604) || (index >= 0x1A00 && index < 0x1A04);
}

}  // namespace

SimDrive::SimDrive(const SimDriveConfig& config, can::CanChannel& channel)
    : m_node(config.node), m_channel(channel), m_sdo(m_od, *this), m_bootTime(config.bootTime) {
    m_sdo.setNode(m_node);
    m_plant.configure(config.plant);
    m_plant.reset(config.initialPosition);
    buildDictionary(config);
}

void SimDrive::buildDictionary(const SimDriveConfig& c) {
    using T = ObjectType;
    constexpr Access ro = Access::ReadOnly;
    constexpr Access rw = Access::ReadWrite;
    ObjectDictionary& od = m_od;
    od.add({0x1000, 0}, T::U32, ro, kSimDeviceType);
    od.add(kErrorRegister, T::U8, ro, 0);
    od.addText({0x1008, 0}, ro, c.deviceName);
    od.addText({0x100A, 0}, ro, "1.0.0");
    od.add({0x1016, 0}, T::U8, ro, 1);
    od.add(kConsumerHeartbeat, T::U32, rw, 0);
    od.add(kProducerHeartbeat, T::U16, rw, 0);
    od.add({0x1018, 0}, T::U8, ro, 4);
    od.add({0x1018, 1}, T::U32, ro, c.vendorId);
    od.add({0x1018, 2}, T::U32, ro, c.productCode);
    od.add({0x1018, 3}, T::U32, ro, c.revision);
    od.add({0x1018, 4}, T::U32, ro, c.serial);
    for (int n = 1; n <= kPdoCount; ++n) {
        uint16_t rpdoComm = canopen::pdoCommunicationIndex(false, n);
        uint16_t tpdoComm = canopen::pdoCommunicationIndex(true, n);
        od.add({rpdoComm, 0}, T::U8, ro, 2);
        od.add({rpdoComm, 1}, T::U32, rw, 0);
        od.add({rpdoComm, 2}, T::U8, rw, 255);
        od.add({tpdoComm, 0}, T::U8, ro, 5);
        od.add({tpdoComm, 1}, T::U32, rw, 0);
        od.add({tpdoComm, 2}, T::U8, rw, 255);
        od.add({tpdoComm, 3}, T::U16, rw, 0);
        od.add({tpdoComm, 5}, T::U16, rw, 0);
        for (bool transmit : {false, true}) {
            uint16_t mapping = canopen::pdoMappingIndex(transmit, n);
            od.add({mapping, 0}, T::U8, rw, 0);
            for (uint8_t sub = 1; sub <= canopen::kMaxPdoEntries; ++sub)
                od.add({mapping, sub}, T::U32, rw, 0);
        }
    }
    od.addText({0x2001, 0}, rw, "");
    od.add(kAbortConnection, T::I16, rw, 1);
    od.add(kErrorCode, T::U16, ro, 0, Mapping::Transmit);
    od.add(kControlword, T::U16, rw, 0, Mapping::Receive);
    od.add(kStatusword, T::U16, ro, 0, Mapping::Transmit);
    od.add(kQuickStopOption, T::I16, rw, 2);
    od.add({0x605E, 0}, T::I16, rw, 2);
    od.add(kModes, T::I8, rw, 0, Mapping::Receive);
    od.add(kModesDisplay, T::I8, ro, 0, Mapping::Transmit);
    od.add(kPositionActual, T::I32, ro, 0, Mapping::Transmit);
    od.add(kFollowingErrorWindow, T::U32, rw, 0xFFFFFFFFu);
    od.add(kFollowingErrorTimeout, T::U16, rw, 10);
    od.add(kVelocityActual, T::I32, ro, 0, Mapping::Transmit);
    od.add(kTorqueActual, T::I16, ro, 0, Mapping::Transmit);
    od.add(kTargetPosition, T::I32, rw, 0, Mapping::Receive);
    od.add({0x607D, 0}, T::U8, ro, 2);
    od.add(kLimitMin, T::I32, rw, 0x80000000u);
    od.add(kLimitMax, T::I32, rw, 0x7FFFFFFFu);
    auto accel = static_cast<uint32_t>(std::min(c.plant.maxAcceleration, 4.0e9));
    od.add(kProfileAccel, T::U32, rw, accel);
    od.add(kProfileDecel, T::U32, rw, accel);
    od.add(kQuickStopDecel, T::U32, rw, accel);
    od.add({0x60C2, 0}, T::U8, ro, 2);
    od.add(kInterpolationValue, T::U8, rw, 1);
    od.add(kInterpolationExponent, T::I8, rw, static_cast<uint8_t>(-3));
    od.add(kFollowingErrorActual, T::I32, ro, 0, Mapping::Transmit);
    od.add(kTargetVelocity, T::I32, rw, 0, Mapping::Receive);
    od.add(kSupportedModes, T::U32, ro, kSimSupportedModes);
    resetCommunication();
}

// CiA 301 defaults of the communication objects: RPDO1 = controlword, TPDO1 = statusword,
// event-driven; the other PDOs exist with no mapping.
void SimDrive::resetCommunication() noexcept {
    for (int n = 1; n <= kPdoCount; ++n) {
        m_od.set({canopen::pdoCommunicationIndex(false, n), 1}, canopen::rpdoCobId(n, m_node));
        m_od.set({canopen::pdoCommunicationIndex(false, n), 2}, 255);
        m_od.set({canopen::pdoCommunicationIndex(true, n), 1}, canopen::tpdoCobId(n, m_node));
        m_od.set({canopen::pdoCommunicationIndex(true, n), 2}, 255);
        m_od.set({canopen::pdoCommunicationIndex(true, n), 3}, 0);
        m_od.set({canopen::pdoCommunicationIndex(true, n), 5}, 0);
        for (bool transmit : {false, true}) {
            uint16_t mapping = canopen::pdoMappingIndex(transmit, n);
            for (uint8_t sub = 0; sub <= canopen::kMaxPdoEntries; ++sub)
                m_od.set({mapping, sub}, 0);
        }
        m_rpdo[static_cast<size_t>(n - 1)] = Rpdo{};
        m_tpdo[static_cast<size_t>(n - 1)] = Tpdo{};
    }
    m_od.set({0x1600, 0}, 1);
    m_od.set({0x1600, 1}, 0x60400010);
    m_od.set({0x1A00, 0}, 1);
    m_od.set({0x1A00, 1}, 0x60410010);
    m_od.set(kProducerHeartbeat, 0);
    m_od.set(kConsumerHeartbeat, 0);
    m_heartbeat.configure(m_node, std::chrono::milliseconds(0), m_now);
    m_consumer.configure(0, 0);
    m_sdo.reset();
}

void SimDrive::powerOn(nanoseconds now) noexcept {
    m_powered = true;
    m_now = now;
    m_booting = true;
    m_bootAt = now + m_bootTime;
    m_state = State::NotReadyToSwitchOn;
}

void SimDrive::finishBoot(nanoseconds now) noexcept {
    m_booting = false;
    m_nmt = NmtState::PreOperational;
    // Transitions 0 and 1: self-test passed.
    if (m_state == State::NotReadyToSwitchOn) enterState(State::SwitchOnDisabled, now);
    send(canopen::heartbeatFrame(m_node, NmtState::BootUp));
    m_heartbeat.configure(m_node, std::chrono::milliseconds(m_od.get(kProducerHeartbeat)), now);
}

uint16_t SimDrive::errorCode() const noexcept {
    return static_cast<uint16_t>(m_od.get(kErrorCode));
}

void SimDrive::send(const can::CanFrame& frame) noexcept {
    if (!m_silent) m_outbox.push(frame);
}

void SimDrive::emcy(uint16_t code) noexcept {
    canopen::Emcy e;
    e.code = code;
    e.errorRegister =
        static_cast<uint8_t>(m_od.get(kErrorRegister) | canopen::errorRegisterFor(code));
    send(canopen::emcyFrame(m_node, e));
}

void SimDrive::injectFault(uint16_t code, nanoseconds now) noexcept {
    if (m_state == State::Fault || m_state == State::FaultReactionActive) return;
    m_od.set(kErrorCode, code);
    m_od.set(kErrorRegister, canopen::errorRegisterFor(code));
    emcy(code);
    enterState(State::FaultReactionActive, now);
}

void SimDrive::injectEmcyWarning(uint16_t code) noexcept {
    emcy(code);
}

void SimDrive::injectEncoderLoss(nanoseconds now) noexcept {
    m_frozenPosition = static_cast<int32_t>(m_od.get(kPositionActual));
    m_encoderLost = true;
    injectFault(kEmcyEncoder, now);
}

void SimDrive::goSilent() noexcept {
    m_silent = true;
    m_outbox.clear();
    m_plant.torqueOff();
}

void SimDrive::setIdentity(uint32_t vendorId, uint32_t productCode) noexcept {
    m_od.set({0x1018, 1}, vendorId);
    m_od.set({0x1018, 2}, productCode);
}

void SimDrive::injectSdoAbort(ObjectAddress address, uint32_t code) noexcept {
    m_abortAddress = address;
    m_abortCode = code;
}

uint32_t SimDrive::tpdoCobId(int number) const noexcept {
    return m_od.get({canopen::pdoCommunicationIndex(true, number), 1});
}

uint32_t SimDrive::rpdoCobId(int number) const noexcept {
    return m_od.get({canopen::pdoCommunicationIndex(false, number), 1});
}

double SimDrive::interpolationPeriodS() const noexcept {
    double value = m_od.get(kInterpolationValue);
    int exponent = m_od.getSigned(kInterpolationExponent);
    return value * std::pow(10.0, exponent);
}

uint16_t SimDrive::statusword() const noexcept {
    auto sw = static_cast<uint16_t>(cia402::statuswordFor(m_state) | cia402::kStatusRemote);
    auto mode = static_cast<int8_t>(m_od.getSigned(kModesDisplay));
    if (m_state == State::OperationEnabled) {
        if (mode == kModeCsp || mode == kModeCsv) sw |= cia402::kStatusFollowsTarget;
        if (mode == kModeCsp && m_followingErrorActive) sw |= cia402::kStatusFollowingError;
        if (m_limitActive) sw |= cia402::kStatusInternalLimit;
        if (mode == kModeProfileVelocity &&
            std::fabs(m_plant.velocity() - m_od.getSigned(kTargetVelocity)) < 1.0) {
            sw |= cia402::kStatusTargetReached;
        }
    }
    if (m_state == State::QuickStopActive && m_plant.rampDone()) sw |= cia402::kStatusTargetReached;
    return sw;
}

void SimDrive::enterState(State state, nanoseconds) noexcept {
    State from = m_state;
    m_state = state;
    // The injected overload is the axis driving into something: once the drive stops driving
    // (its own trip, a quick stop), it no longer pushes, and the stop ends at rest.
    if (from == State::OperationEnabled && state != State::OperationEnabled) m_plant.setDrift(0.0);
    auto option = static_cast<int16_t>(m_od.getSigned(kQuickStopOption));
    double quickStopDecel = m_od.get(kQuickStopDecel);
    switch (state) {
        case State::OperationEnabled:
            if (m_od.getSigned(kModesDisplay) == kModeCsp) {
                m_plant.hold();
            } else {
                m_plant.velocityTo(0.0, 0.0);
            }
            break;
        case State::QuickStopActive:
            if (option == 0) {
                m_plant.torqueOff();
            } else {
                double decel =
                    option == 1 || option == 5 ? m_od.get(kProfileDecel) : quickStopDecel;
                m_plant.rampDown(decel, option >= 5);
            }
            break;
        case State::SwitchedOn:
            // Transition 5: disable operation slows down first (0x605C = 1).
            if (from == State::OperationEnabled)
                m_plant.rampDown(m_od.get(kProfileDecel), false);
            else
                m_plant.torqueOff();
            break;
        case State::FaultReactionActive:
            m_plant.rampDown(quickStopDecel, false);
            break;
        default:
            m_plant.torqueOff();
            break;
    }
    m_followingErrorActive = false;
}

void SimDrive::processControlword(uint16_t cw, nanoseconds now) noexcept {
    uint16_t previous = m_lastControlword;
    m_lastControlword = cw;
    if (m_state == State::Fault) {
        // Transition 15 on the rising edge of bit 7, unless the cause is still there.
        if ((cw & 0x80) && !(previous & 0x80) && !m_encoderLost) {
            m_od.set(kErrorCode, 0);
            m_od.set(kErrorRegister, 0);
            m_plant.setDrift(0.0);
            enterState(State::SwitchOnDisabled, now);
            emcy(0x0000);
        }
        return;
    }
    const cia402::Transition* t = cia402::transitionFor(m_state, cw);
    if (!t) return;
    auto option = m_od.getSigned(kQuickStopOption);
    if (t->number == 16 && (option < 5 || option > 8)) return;  // only with 0x605A = 5..8
    enterState(t->to, now);
}

void SimDrive::applyTargets() noexcept {
    if (m_state != State::OperationEnabled) return;
    auto mode = static_cast<int8_t>(m_od.getSigned(kModesDisplay));
    if (mode == kModeCsp) {
        int32_t target = m_od.getSigned(kTargetPosition);
        int32_t lo = m_od.getSigned(kLimitMin);
        int32_t hi = m_od.getSigned(kLimitMax);
        m_limitActive = lo < hi && (target < lo || target > hi);
        if (lo < hi) target = std::clamp(target, lo, hi);
        // The INT32 target wraps like the position: step from the current command.
        double reference = m_plant.command();
        int32_t step = static_cast<int32_t>(static_cast<uint32_t>(target) -
                                            static_cast<uint32_t>(wrap32(reference)));
        m_plant.interpolateTo(std::nearbyint(reference) + step, interpolationPeriodS());
    } else if (mode == kModeCsv) {
        m_plant.velocityTo(m_od.getSigned(kTargetVelocity), 0.0);
    } else if (mode == kModeProfileVelocity) {
        m_plant.velocityTo(m_od.getSigned(kTargetVelocity), m_od.get(kProfileAccel));
    }
}

void SimDrive::sample() noexcept {
    int32_t position = m_encoderLost ? m_frozenPosition : wrap32(m_plant.position());
    m_od.set(kPositionActual, static_cast<uint32_t>(position));
    m_od.set(kVelocityActual, static_cast<uint32_t>(wrap32(m_plant.velocity())));
    m_od.set(kFollowingErrorActual, static_cast<uint32_t>(wrap32(m_plant.followingError())));
    double torque = m_plant.acceleration() / 1.0e8 * 1000.0;
    m_od.set(kTorqueActual,
             static_cast<uint32_t>(static_cast<int16_t>(std::clamp(torque, -32768.0, 32767.0))));
    m_od.set(kStatusword, statusword());
}

size_t SimDrive::packTpdo(int number, std::array<uint8_t, 8>& data) const noexcept {
    uint16_t mapping = canopen::pdoMappingIndex(true, number);
    auto count = static_cast<uint8_t>(m_od.get({mapping, 0}));
    size_t offset = 0;
    data.fill(0);
    for (uint8_t i = 1; i <= count && i <= canopen::kMaxPdoEntries; ++i) {
        canopen::PdoEntry e = canopen::PdoEntry::fromValue(m_od.get({mapping, i}));
        size_t bytes = e.bits / 8u;
        if (offset + bytes > data.size()) break;
        canopen::packField(data, offset, bytes, m_od.get({e.index, e.subIndex}));
        offset += bytes;
    }
    return offset;
}

void SimDrive::sendTpdo(int number, nanoseconds now) noexcept {
    // A PDO that maps nothing is not sent (CiA 301: mapping disabled).
    if (m_od.get({canopen::pdoMappingIndex(true, number), 0}) == 0) return;
    Tpdo& t = m_tpdo[static_cast<size_t>(number - 1)];
    can::CanFrame f;
    f.id = tpdoCobId(number) & can::kStandardIdMask;
    f.length = static_cast<uint8_t>(packTpdo(number, f.data));
    t.lastSent = f.data;
    t.lastTime = now;
    t.sentOnce = true;
    if (!m_tpdosStopped) send(f);
}

void SimDrive::applyRpdo(int number, const Rpdo& rpdo, nanoseconds now) noexcept {
    uint16_t mapping = canopen::pdoMappingIndex(false, number);
    auto count = static_cast<uint8_t>(m_od.get({mapping, 0}));
    size_t offset = 0;
    bool controlword = false;
    for (uint8_t i = 1; i <= count && i <= canopen::kMaxPdoEntries; ++i) {
        canopen::PdoEntry e = canopen::PdoEntry::fromValue(m_od.get({mapping, i}));
        size_t bytes = e.bits / 8u;
        if (offset + bytes > rpdo.length) break;  // too short: CiA 301 ignores the rest
        ObjectEntry* entry = m_od.find({e.index, e.subIndex});
        if (entry) m_od.setBytes(*entry, {rpdo.data.data() + offset, bytes});
        controlword = controlword || (e.index == kControlword.index);
        offset += bytes;
    }
    if (controlword) processControlword(static_cast<uint16_t>(m_od.get(kControlword)), now);
}

void SimDrive::onSync(nanoseconds now) noexcept {
    if (m_nmt != NmtState::Operational) return;
    ++m_syncs;
    for (int n = 1; n <= kPdoCount; ++n) {
        Rpdo& r = m_rpdo[static_cast<size_t>(n - 1)];
        if (r.latched) {
            r.latched = false;
            applyRpdo(n, r, now);
        }
    }
    applyTargets();
    sample();
    for (int n = 1; n <= kPdoCount; ++n) {
        uint32_t cobId = tpdoCobId(n);
        auto type = m_od.get({canopen::pdoCommunicationIndex(true, n), 2});
        if ((cobId & canopen::kPdoInvalid) || type == 0 || type > 240) continue;
        if (m_syncs % type == 0) sendTpdo(n, now);
    }
}

void SimDrive::onNmt(const can::CanFrame& f, nanoseconds now) noexcept {
    if (f.length != 2 || (f.data[1] != 0 && f.data[1] != m_node)) return;
    switch (static_cast<canopen::NmtCommand>(f.data[0])) {
        case canopen::NmtCommand::Start:
            m_nmt = NmtState::Operational;
            break;
        case canopen::NmtCommand::Stop:
            m_nmt = NmtState::Stopped;
            break;
        case canopen::NmtCommand::EnterPreOperational:
            m_nmt = NmtState::PreOperational;
            break;
        case canopen::NmtCommand::ResetNode:
            if (!m_encoderLost) m_od.set(kErrorCode, 0);
            enterState(State::NotReadyToSwitchOn, now);
            [[fallthrough]];
        case canopen::NmtCommand::ResetCommunication:
            resetCommunication();
            m_booting = true;
            m_bootAt = now + m_bootTime;
            break;
    }
}

void SimDrive::onFrame(const can::CanFrame& f, nanoseconds now) noexcept {
    if (f.extended || f.remote) return;
    if (f.id == canopen::kNmtId) return onNmt(f, now);
    if (m_nmt == NmtState::Stopped) return;  // only NMT and heartbeat in Stopped
    if (f.id == canopen::kSyncId) return onSync(now);
    if (f.id == canopen::kSdoRequestBase + m_node) return m_sdo.onRequest(f, m_outbox);
    if (canopen::functionCode(f.id) == canopen::kHeartbeatBase) {
        uint8_t node = 0;
        NmtState state{};
        if (!canopen::parseHeartbeat(f, node, state)) return;
        const canopen::HeartbeatConsumer::Entry* e = m_consumer.find(node);
        if (!e) return;
        // CiA 301: supervision starts with the first heartbeat.
        if (!e->armed) m_consumer.arm(node, now);
        m_consumer.onHeartbeat(node, state, now);
        return;
    }
    if (m_nmt != NmtState::Operational) return;
    for (int n = 1; n <= kPdoCount; ++n) {
        uint32_t cobId = rpdoCobId(n);
        if ((cobId & canopen::kPdoInvalid) || f.id != (cobId & can::kStandardIdMask)) continue;
        Rpdo& r = m_rpdo[static_cast<size_t>(n - 1)];
        r.data = f.data;
        r.length = f.length;
        auto type = m_od.get({canopen::pdoCommunicationIndex(false, n), 2});
        if (type <= 240) {
            r.latched = true;  // synchronous: applied at the next SYNC
        } else {
            applyRpdo(n, r, now);
        }
        return;
    }
}

void SimDrive::runTimers(nanoseconds now) noexcept {
    if (m_booting) {
        if (now >= m_bootAt) finishBoot(now);
        return;
    }
    if (m_state == State::OperationEnabled && m_od.getSigned(kModesDisplay) == kModeCsp) {
        uint32_t window = m_od.get(kFollowingErrorWindow);
        nanoseconds timeout = std::chrono::milliseconds(m_od.get(kFollowingErrorTimeout));
        if (window != 0xFFFFFFFFu && std::fabs(m_plant.followingError()) > window) {
            if (!m_followingErrorActive) {
                m_followingErrorActive = true;
                m_followingErrorSince = now;
            } else if (now - m_followingErrorSince >= timeout) {
                injectFault(kEmcyFollowingError, now);
            }
        } else {
            m_followingErrorActive = false;
        }
    }
    if (m_state == State::FaultReactionActive && m_plant.rampDone()) {
        enterState(State::Fault, now);  // transition 14
    }
    auto option = m_od.getSigned(kQuickStopOption);
    if (m_state == State::QuickStopActive && (option == 1 || option == 2) && m_plant.rampDone()) {
        enterState(State::SwitchOnDisabled, now);  // transition 12
    }
    if (!m_heartbeatStopped) m_heartbeat.advance(now, m_nmt, m_outbox);
    if (m_consumer.nextTimeout(now)) {
        // The drive's own reaction to a lost master (0x6007); one EMCY 0x8130 either way.
        int32_t reaction = m_od.getSigned(kAbortConnection);
        if (reaction != 1) emcy(kEmcyHeartbeat);
        switch (reaction) {
            case 1:
                injectFault(kEmcyHeartbeat, now);
                break;
            case 2:
                if (m_state == State::OperationEnabled) enterState(State::SwitchOnDisabled, now);
                break;
            case 3:
                if (m_state == State::OperationEnabled) enterState(State::QuickStopActive, now);
                break;
            default:
                break;
        }
    }
    if (m_nmt == NmtState::Operational) {
        // Event-driven TPDOs: on change (not before the inhibit time) or on the event timer.
        sample();
        for (int n = 1; n <= kPdoCount; ++n) {
            uint16_t comm = canopen::pdoCommunicationIndex(true, n);
            uint32_t type = m_od.get({comm, 2});
            if ((tpdoCobId(n) & canopen::kPdoInvalid) || type < 254) continue;
            Tpdo& t = m_tpdo[static_cast<size_t>(n - 1)];
            std::array<uint8_t, 8> data{};
            packTpdo(n, data);
            nanoseconds inhibit = std::chrono::microseconds(100 * m_od.get({comm, 3}));
            nanoseconds timer = std::chrono::milliseconds(m_od.get({comm, 5}));
            bool changed = !t.sentOnce || data != t.lastSent;
            bool timerDue = timer.count() > 0 && now - t.lastTime >= timer;
            if ((changed && now - t.lastTime >= inhibit) || timerDue) sendTpdo(n, now);
        }
    }
}

void SimDrive::poll(nanoseconds now) noexcept {
    if (!m_powered) return;
    if (now > m_now) {
        m_plant.advance(std::chrono::duration<double>(now - m_now).count());
        m_now = now;
    }
    // CiA 301: the node reports its controller going error passive (EMCY 0x8120).
    can::ControllerState controller = m_channel.state();
    if (controller != m_controller && controller == can::ControllerState::ErrorPassive &&
        booted()) {
        emcy(kEmcyErrorPassive);
    }
    m_controller = controller;
    can::CanFrame frame;
    for (int n = 0; n < 256 && m_channel.receive(frame); ++n) {
        if (!m_booting && !m_silent) onFrame(frame, now);
    }
    if (!m_silent) runTimers(now);
    while (!m_outbox.empty()) {
        if (!m_silent) m_channel.send(m_outbox.front());
        m_outbox.pop();
    }
}

nanoseconds SimDrive::nextDeadline() const noexcept {
    nanoseconds next = nanoseconds::max();
    if (!m_powered || m_silent) return next;
    if (m_booting) return m_bootAt;
    if (m_heartbeat.active() && !m_heartbeatStopped) next = std::min(next, m_heartbeat.next());
    if (const canopen::HeartbeatConsumer::Entry* e =
            m_consumer.find(static_cast<uint8_t>(m_od.get(kConsumerHeartbeat) >> 16))) {
        if (e->armed && !e->timedOut)
            next = std::min(next, e->lastSeen + e->timeout + nanoseconds(1));
    }
    if (m_followingErrorActive) {
        next = std::min(next, m_followingErrorSince +
                                  std::chrono::milliseconds(m_od.get(kFollowingErrorTimeout)));
    }
    return next;
}

uint32_t SimDrive::accessAbort(ObjectAddress address) noexcept {
    return m_abortCode != 0 && address == m_abortAddress ? m_abortCode : 0;
}

uint32_t SimDrive::checkWrite(const ObjectEntry& entry, std::span<const uint8_t> bytes) noexcept {
    uint16_t index = entry.address.index;
    uint8_t sub = entry.address.subIndex;
    uint32_t value = bytesValue(bytes);
    if (isPdoCommunication(index) || isPdoMapping(index)) {
        // PDOs are (re)mapped in Pre-operational only (CiA 301; the spec's 0x08000022).
        if (m_nmt == NmtState::Operational) return abortCode(SdoAbort::DeviceState);
    }
    if (isPdoCommunication(index) && sub == 1) {
        uint32_t current = entry.value;
        bool valid = !(current & canopen::kPdoInvalid);
        bool stillValid = !(value & canopen::kPdoInvalid);
        // The identifier of an existing PDO changes only through the invalid state.
        if (valid && stillValid && (value & 0x7FF) != (current & 0x7FF)) {
            return abortCode(SdoAbort::InvalidValue);
        }
    }
    if (isPdoMapping(index)) {
        bool transmit = index >= 0x1A00;
        auto number = static_cast<int>(index - (transmit ? 0x1A00 : 0x1600) + 1);
        uint32_t cobId = m_od.get({canopen::pdoCommunicationIndex(transmit, number), 1});
        if (!(cobId & canopen::kPdoInvalid)) return abortCode(SdoAbort::DeviceState);
        if (sub == 0) {
            if (value > canopen::kMaxPdoEntries) return abortCode(SdoAbort::ValueTooHigh);
            unsigned bits = 0;
            for (uint8_t i = 1; i <= value; ++i)
                bits += m_od.get({index, i}) & 0xFF;
            if (bits > 64) return abortCode(SdoAbort::MappingTooLong);
        } else {
            if (m_od.get({index, 0}) != 0) return abortCode(SdoAbort::DeviceState);
            if (value != 0) {
                canopen::PdoEntry e = canopen::PdoEntry::fromValue(value);
                const ObjectEntry* target = m_od.find({e.index, e.subIndex});
                Mapping wanted = transmit ? Mapping::Transmit : Mapping::Receive;
                if (!target || target->mapping != wanted || e.bits != typeSize(target->type) * 8) {
                    return abortCode(SdoAbort::NotMappable);
                }
            }
        }
    }
    auto signedValue = [&]() -> int32_t {
        return entry.type == ObjectType::I8    ? static_cast<int8_t>(value & 0xFF)
               : entry.type == ObjectType::I16 ? static_cast<int16_t>(value & 0xFFFF)
                                               : static_cast<int32_t>(value);
    };
    if (entry.address == kModes) {
        int32_t mode = signedValue();
        if (mode < 1 || mode > 32 || !(m_od.get(kSupportedModes) >> (mode - 1) & 1u)) {
            return abortCode(SdoAbort::InvalidValue);
        }
    }
    if (entry.address == kQuickStopOption) {
        int32_t option = signedValue();
        if (option != 0 && option != 1 && option != 2 && option != 5 && option != 6) {
            return abortCode(SdoAbort::InvalidValue);
        }
    }
    if (entry.address == kAbortConnection && (signedValue() < 0 || signedValue() > 3)) {
        return abortCode(SdoAbort::InvalidValue);
    }
    if (entry.address == kInterpolationExponent && (signedValue() < -6 || signedValue() > 0)) {
        return abortCode(SdoAbort::InvalidValue);
    }
    if (entry.address == kInterpolationValue && value == 0) return abortCode(SdoAbort::ValueTooLow);
    return 0;
}

void SimDrive::written(const ObjectEntry& entry) noexcept {
    if (entry.address == kProducerHeartbeat) {
        m_heartbeat.configure(m_node, std::chrono::milliseconds(entry.value), m_now);
    } else if (entry.address == kConsumerHeartbeat) {
        m_consumer.configure(0, entry.value);
    } else if (entry.address == kModes) {
        m_od.set(kModesDisplay, entry.value);
    } else if (entry.address == kControlword) {
        processControlword(static_cast<uint16_t>(entry.value), m_now);
    }
}

}  // namespace kerf::drivers::sim
