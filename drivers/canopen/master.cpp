#include "drivers/canopen/master.h"

#include <stdexcept>

#include "drivers/canopen/cob_id.h"
#include "drivers/canopen/master_error.h"

namespace kerf::drivers::canopen {

const char* nodePhaseName(NodePhase phase) noexcept {
    switch (phase) {
        case NodePhase::Idle:
            return "idle";
        case NodePhase::Resetting:
            return "waiting for boot-up";
        case NodePhase::Configuring:
            return "configuring";
        case NodePhase::Configured:
            return "configured";
        case NodePhase::Starting:
            return "starting";
        case NodePhase::Operational:
            return "operational";
        case NodePhase::Failed:
            return "boot failed";
        case NodePhase::Lost:
            return "lost";
    }
    return "?";
}

Master::Master(MasterConfig config) : m_config(std::move(config)) {
    if (m_config.nodes.size() > kMaxNodes) throw std::invalid_argument("too many CANopen nodes");
    m_index.fill(-1);
    m_nodes.resize(m_config.nodes.size());
    auto timeoutMs = static_cast<uint16_t>(m_config.heartbeatTimeout.count());
    for (size_t i = 0; i < m_nodes.size(); ++i) {
        Node& n = m_nodes[i];
        n.config = std::move(m_config.nodes[i]);
        uint8_t id = n.config.id;
        if (id == 0 || id > kMaxNodeId || m_index[id] >= 0 || id == m_config.masterNode) {
            throw std::invalid_argument(
                "CANopen node-IDs must be 1..127, unique, not the master's");
        }
        m_index[id] = static_cast<int8_t>(i);
        n.sdo.configure(id, m_config.sdoTimeout);
        n.values.assign(n.config.boot.steps().size(), 0);
        m_consumer.configure(i, heartbeatConsumerEntry(id, timeoutMs));
    }
    m_config.nodes.clear();
    m_sync.configure(m_config.cyclePeriod);
}

void Master::emit(MasterEventKind kind, size_t i, std::chrono::nanoseconds now) noexcept {
    MasterEvent e;
    e.kind = kind;
    e.nodeIndex = i;
    e.node = m_nodes[i].config.id;
    e.time = now;
    e.error = m_nodes[i].error;
    e.object = m_nodes[i].failedObject;
    m_events.push(e);
}

void Master::fail(size_t i, NodePhase phase, std::error_code error,
                  std::chrono::nanoseconds now) noexcept {
    Node& n = m_nodes[i];
    n.phase = phase;
    n.error = error;
    n.phaseStart = now;
    m_consumer.disarm(n.config.id);
}

void Master::start(std::chrono::nanoseconds now) noexcept {
    m_started = true;
    if (m_config.masterNode != 0)
        m_heartbeat.configure(m_config.masterNode, m_config.heartbeatPeriod, now);
    for (size_t i = 0; i < m_nodes.size(); ++i)
        restartNode(i, now);
}

void Master::restartNode(size_t i, std::chrono::nanoseconds now) noexcept {
    Node& n = m_nodes[i];
    n.sdo.cancel();
    n.phase = NodePhase::Resetting;
    n.phaseStart = now;
    n.step = 0;
    n.error.clear();
    n.failedObject = {};
    n.syncsWithoutTpdo = 0;
    m_consumer.disarm(n.config.id);
    m_outbox.push(nmtFrame(NmtCommand::ResetCommunication, n.config.id));
}

std::span<uint8_t> Master::rpdo(size_t i) noexcept {
    return {m_nodes[i].rpdo.data(), m_nodes[i].config.rpdo.byteLength()};
}

uint32_t Master::bootValue(size_t i, size_t step) const noexcept {
    const auto& values = m_nodes[i].values;
    return step < values.size() ? values[step] : 0;
}

bool Master::allOperational() const noexcept {
    for (const Node& n : m_nodes) {
        if (n.phase != NodePhase::Operational) return false;
    }
    return !m_nodes.empty();
}

bool Master::popEvent(MasterEvent& event) noexcept {
    if (m_events.empty()) return false;
    event = m_events.front();
    m_events.pop();
    return true;
}

bool Master::issueStep(size_t i, std::chrono::nanoseconds now) noexcept {
    Node& n = m_nodes[i];
    const BootStep& s = n.config.boot.steps()[n.step];
    if (s.kind == BootStepKind::Write) {
        std::array<uint8_t, 4> bytes{};
        packField(bytes, 0, s.size, s.value);
        return n.sdo.download(s.address, {bytes.data(), s.size}, now, m_outbox);
    }
    return n.sdo.upload(s.address, now, m_outbox);
}

void Master::runBoot(size_t i, std::chrono::nanoseconds now) noexcept {
    Node& n = m_nodes[i];
    const auto& steps = n.config.boot.steps();
    if (n.sdo.status() == SdoStatus::Failed) {
        n.failedObject = steps[n.step].address;
        fail(i, NodePhase::Failed, n.sdo.error(), now);
        n.sdo.acknowledge();
        emit(MasterEventKind::BootFailed, i, now);
        return;
    }
    if (n.sdo.status() == SdoStatus::Done) {
        const BootStep& s = steps[n.step];
        n.values[n.step] = n.sdo.value();
        n.sdo.acknowledge();
        if (s.kind == BootStepKind::Expect && (n.values[n.step] & s.mask) != s.value) {
            n.failedObject = s.address;
            fail(i, NodePhase::Failed, s.mismatch, now);
            emit(MasterEventKind::BootFailed, i, now);
            return;
        }
        ++n.step;
    }
    if (n.sdo.status() != SdoStatus::Idle) return;
    if (n.step == steps.size()) {
        n.phase = NodePhase::Configured;
        n.phaseStart = now;
        emit(MasterEventKind::Configured, i, now);
        return;
    }
    issueStep(i, now);
}

void Master::startConfiguredNodes(std::chrono::nanoseconds now) noexcept {
    for (const Node& n : m_nodes) {
        if (n.phase != NodePhase::Configured && n.phase != NodePhase::Starting &&
            n.phase != NodePhase::Operational) {
            return;
        }
    }
    if (!m_sync.running()) m_sync.start(now);
    for (Node& n : m_nodes) {
        if (n.phase != NodePhase::Configured) continue;
        m_outbox.push(nmtFrame(NmtCommand::Start, n.config.id));
        n.phase = NodePhase::Starting;
        n.phaseStart = now;
        n.syncsWithoutTpdo = 0;
        m_consumer.arm(n.config.id, now);
    }
}

void Master::setOperational(size_t i, std::chrono::nanoseconds now) noexcept {
    if (m_nodes[i].phase != NodePhase::Starting) return;
    m_nodes[i].phase = NodePhase::Operational;
    m_nodes[i].phaseStart = now;
    emit(MasterEventKind::Operational, i, now);
}

void Master::onHeartbeat(size_t i, NmtState state, std::chrono::nanoseconds now) noexcept {
    Node& n = m_nodes[i];
    m_consumer.onHeartbeat(n.config.id, state, now);
    switch (n.phase) {
        case NodePhase::Resetting:
            if (state == NmtState::BootUp) {
                n.phase = NodePhase::Configuring;
                n.phaseStart = now;
            }
            break;
        case NodePhase::Starting:
            // A pre-operational heartbeat may still have been on its way when the start went out.
            if (state == NmtState::Operational) setOperational(i, now);
            break;
        case NodePhase::Operational:
            if (state != NmtState::Operational) {
                fail(i, NodePhase::Lost, MasterErrc::UnexpectedNmtState, now);
                MasterEvent e;
                e.kind = MasterEventKind::UnexpectedState;
                e.nodeIndex = i;
                e.node = n.config.id;
                e.time = now;
                e.error = n.error;
                e.state = state;
                m_events.push(e);
            }
            break;
        default:
            break;
    }
}

void Master::onFrame(const can::CanFrame& f, std::chrono::nanoseconds now) noexcept {
    if (f.extended || f.remote || f.id == kNmtId || f.id == kSyncId) return;
    uint8_t id = nodeOf(f.id);
    int index = m_index[id];
    if (index < 0) return;
    auto i = static_cast<size_t>(index);
    Node& n = m_nodes[i];
    switch (functionCode(f.id)) {
        case kHeartbeatBase: {
            uint8_t node = 0;
            NmtState state{};
            if (parseHeartbeat(f, node, state)) onHeartbeat(i, state, now);
            return;
        }
        case kSdoResponseBase:
            n.sdo.onFrame(f, now, m_outbox);
            return;
        case kEmcyBase: {
            MasterEvent e;
            uint8_t node = 0;
            if (!parseEmcy(f, node, e.emcy)) return;
            e.kind = MasterEventKind::Emergency;
            e.nodeIndex = i;
            e.node = id;
            e.time = now;
            m_events.push(e);
            return;
        }
        default:
            break;
    }
    // A lost node that still speaks keeps reporting: the stop is watched to standstill.
    if (f.id == n.config.tpdo.cobId &&
        (n.phase == NodePhase::Starting || n.phase == NodePhase::Operational ||
         n.phase == NodePhase::Lost)) {
        n.tpdo.data = f.data;
        n.tpdo.length = f.length;
        n.tpdo.time = now;
        ++n.tpdo.sequence;
        n.syncsWithoutTpdo = 0;
        // PDOs only flow in Operational (CiA 301), so the first TPDO confirms the start.
        setOperational(i, now);
    }
}

void Master::advance(std::chrono::nanoseconds now) noexcept {
    if (!m_started) return;
    for (size_t i = 0; i < m_nodes.size(); ++i) {
        Node& n = m_nodes[i];
        n.sdo.advance(now, m_outbox);
        switch (n.phase) {
            case NodePhase::Resetting:
                if (now - n.phaseStart > m_config.bootUpTimeout) {
                    fail(i, NodePhase::Failed, MasterErrc::BootUpTimeout, now);
                    emit(MasterEventKind::BootFailed, i, now);
                }
                break;
            case NodePhase::Configuring:
                runBoot(i, now);
                break;
            case NodePhase::Starting:
                if (now - n.phaseStart > m_config.heartbeatTimeout) {
                    fail(i, NodePhase::Failed, MasterErrc::NotOperational, now);
                    emit(MasterEventKind::BootFailed, i, now);
                }
                break;
            default:
                break;
        }
    }
    startConfiguredNodes(now);
    while (const HeartbeatConsumer::Entry* e = m_consumer.nextTimeout(now)) {
        auto i = static_cast<size_t>(m_index[e->node]);
        if (m_nodes[i].phase != NodePhase::Starting && m_nodes[i].phase != NodePhase::Operational) {
            continue;
        }
        fail(i, NodePhase::Lost, MasterErrc::HeartbeatLost, now);
        emit(MasterEventKind::HeartbeatLost, i, now);
    }
    m_heartbeat.advance(now, NmtState::Operational, m_outbox);
}

void Master::sendRpdoNow(size_t i) noexcept {
    const Node& n = m_nodes[i];
    // A lost node still gets its RPDO: if it only went quiet, it takes the quick stop.
    if (n.phase != NodePhase::Starting && n.phase != NodePhase::Operational &&
        n.phase != NodePhase::Lost) {
        return;
    }
    can::CanFrame f;
    f.id = n.config.rpdo.cobId;
    f.length = n.config.rpdo.byteLength();
    f.data = n.rpdo;
    m_outbox.push(f);
}

void Master::produceCycle(std::chrono::nanoseconds now) noexcept {
    if (!m_sync.due(now)) return;
    for (size_t i = 0; i < m_nodes.size(); ++i) {
        Node& n = m_nodes[i];
        if (n.phase == NodePhase::Lost) sendRpdoNow(i);
        if (n.phase != NodePhase::Starting && n.phase != NodePhase::Operational) continue;
        uint8_t every = n.config.tpdo.transmissionType;
        if (every >= 1 && every <= 240 &&
            n.syncsWithoutTpdo >= m_config.pdoLossCycles * static_cast<int>(every)) {
            fail(i, NodePhase::Lost, MasterErrc::PdoMissing, now);
            emit(MasterEventKind::PdoMissing, i, now);
            continue;
        }
        ++n.syncsWithoutTpdo;
        sendRpdoNow(i);
    }
    m_outbox.push(m_sync.produce(now));
}

}  // namespace kerf::drivers::canopen
