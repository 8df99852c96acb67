#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

#include "drivers/can/can_frame.h"
#include "drivers/can/fixed_queue.h"
#include "drivers/canopen/boot_plan.h"
#include "drivers/canopen/emcy.h"
#include "drivers/canopen/frame_outbox.h"
#include "drivers/canopen/heartbeat.h"
#include "drivers/canopen/nmt.h"
#include "drivers/canopen/pdo.h"
#include "drivers/canopen/sdo_client.h"
#include "drivers/canopen/sync_producer.h"

// The CANopen master: NMT master, one SDO client per node, boot of every node (reset
// communication, wait for boot-up, run its BootPlan, start), SYNC producer, heartbeat producer
// and consumer, EMCY consumer, and the cyclic RPDO1/TPDO1 exchange with a TPDO presence check.
//
// Passive, as in Lely: the owner's cycle pushes received frames into onFrame(), calls advance()
// with the protocol clock, produceCycle() when cycleDue(), and drains outbox() into the channel.
// No threads, no clock reads. The constructor allocates (configuration thread); every other
// function is for the cycle's thread: noexcept, no allocation, bounded work per call.
namespace kerf::drivers::canopen {

struct MasterNodeConfig {
    uint8_t id = 0;
    BootPlan boot;   // SDO configuration steps, PDO mapping included
    PdoLayout rpdo;  // RPDO1 as the plan maps it: the master packs it every cycle
    PdoLayout tpdo;  // TPDO1: the drive sends it after every SYNC
};

struct MasterConfig {
    uint8_t masterNode = 0;  // node-ID of the master's heartbeat (0x1017 on the master); 0: none
    std::chrono::milliseconds heartbeatPeriod{10};
    std::chrono::milliseconds heartbeatTimeout{30};  // consumer time for every node (0x1016)
    std::chrono::nanoseconds cyclePeriod{std::chrono::milliseconds(1)};  // SYNC period (0x1006)
    std::chrono::nanoseconds sdoTimeout{std::chrono::milliseconds(200)};
    std::chrono::nanoseconds bootUpTimeout{std::chrono::seconds(5)};
    int pdoLossCycles = 3;  // TPDO missing in this many SYNC cycles: the node is lost
    std::vector<MasterNodeConfig> nodes;
};

enum class NodePhase : uint8_t {
    Idle,
    Resetting,    // reset communication sent, waiting for boot-up
    Configuring,  // running the boot plan
    Configured,   // waiting for the other nodes
    Starting,     // start sent, waiting for Operational (heartbeat or first TPDO)
    Operational,
    Failed,  // boot failed (see nodeError)
    Lost,    // heartbeat lost, TPDO missing or unexpected NMT state
};

const char* nodePhaseName(NodePhase phase) noexcept;

enum class MasterEventKind : uint8_t {
    Configured,  // boot plan done
    Operational,
    BootFailed,  // error: SDO abort or MasterErrc; object: where
    HeartbeatLost,
    UnexpectedState,  // state: what the heartbeat said
    PdoMissing,
    Emergency,  // emcy
};

struct MasterEvent {
    MasterEventKind kind = MasterEventKind::Emergency;
    size_t nodeIndex = 0;
    uint8_t node = 0;
    std::chrono::nanoseconds time{0};
    std::error_code error;
    ObjectAddress object;
    NmtState state = NmtState::BootUp;
    Emcy emcy;
};

struct TpdoSlot {
    std::array<uint8_t, 8> data{};
    uint8_t length = 0;
    uint64_t sequence = 0;  // counts received TPDOs: the owner sees new data by a new sequence
    std::chrono::nanoseconds time{0};
};

class Master {
public:
    static constexpr size_t kMaxNodes = 16;
    static constexpr size_t kNodeIdCount = 128;

    explicit Master(MasterConfig config);

    size_t nodeCount() const noexcept { return m_nodes.size(); }
    uint8_t nodeId(size_t i) const noexcept { return m_nodes[i].config.id; }
    const MasterConfig& config() const noexcept { return m_config; }

    // Boots every node: reset communication, boot-up, plan, then start once all are configured.
    void start(std::chrono::nanoseconds now) noexcept;
    // Boots one node again (recovery after it was lost or failed).
    void restartNode(size_t i, std::chrono::nanoseconds now) noexcept;

    void onFrame(const can::CanFrame& frame, std::chrono::nanoseconds now) noexcept;
    void advance(std::chrono::nanoseconds now) noexcept;
    bool cycleDue(std::chrono::nanoseconds now) const noexcept { return m_sync.due(now); }
    // One communication cycle: TPDO presence check, RPDO1 of every started node, then SYNC.
    void produceCycle(std::chrono::nanoseconds now) noexcept;
    // Queues RPDO1 of node i at once, outside the SYNC rhythm (the safety reaction).
    void sendRpdoNow(size_t i) noexcept;

    // RPDO1 payload of node i (rpdo.byteLength() bytes); the owner fills it before produceCycle.
    std::span<uint8_t> rpdo(size_t i) noexcept;
    const TpdoSlot& tpdo(size_t i) const noexcept { return m_nodes[i].tpdo; }
    NodePhase phase(size_t i) const noexcept { return m_nodes[i].phase; }
    std::error_code nodeError(size_t i) const noexcept { return m_nodes[i].error; }
    ObjectAddress failedObject(size_t i) const noexcept { return m_nodes[i].failedObject; }
    // Value read by step `step` of node i's boot plan (Read and Expect steps).
    uint32_t bootValue(size_t i, size_t step) const noexcept;
    bool allOperational() const noexcept;
    bool syncRunning() const noexcept { return m_sync.running(); }
    uint64_t syncCount() const noexcept { return m_sync.produced(); }

    bool popEvent(MasterEvent& event) noexcept;
    FrameOutbox& outbox() noexcept { return m_outbox; }

private:
    struct Node {
        MasterNodeConfig config;
        NodePhase phase = NodePhase::Idle;
        SdoClient sdo;
        size_t step = 0;
        std::vector<uint32_t> values;  // per boot step
        std::chrono::nanoseconds phaseStart{0};
        std::error_code error;
        ObjectAddress failedObject;
        std::array<uint8_t, 8> rpdo{};
        TpdoSlot tpdo;
        int syncsWithoutTpdo = 0;
    };

    void emit(MasterEventKind kind, size_t i, std::chrono::nanoseconds now) noexcept;
    void fail(size_t i, NodePhase phase, std::error_code error,
              std::chrono::nanoseconds now) noexcept;
    void runBoot(size_t i, std::chrono::nanoseconds now) noexcept;
    bool issueStep(size_t i, std::chrono::nanoseconds now) noexcept;
    void startConfiguredNodes(std::chrono::nanoseconds now) noexcept;
    void setOperational(size_t i, std::chrono::nanoseconds now) noexcept;
    void onHeartbeat(size_t i, NmtState state, std::chrono::nanoseconds now) noexcept;

    MasterConfig m_config;
    std::vector<Node> m_nodes;
    std::array<int8_t, kNodeIdCount> m_index{};
    SyncProducer m_sync;
    HeartbeatProducer m_heartbeat;
    HeartbeatConsumer m_consumer;
    FrameOutbox m_outbox;
    can::FixedQueue<MasterEvent, 64> m_events;
    bool m_started = false;
};

}  // namespace kerf::drivers::canopen
