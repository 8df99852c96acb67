#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "drivers/can/can_channel.h"
#include "drivers/can/fixed_queue.h"
#include "drivers/canopen/master.h"
#include "drivers/canopen/protocol_clock.h"
#include "drivers/cia402/drive_axis.h"
#include "drivers/cia402/stop_record.h"
#include "motion/port/drive_bus.h"

// motion's DriveBus over CANopen CiA 402 drives. read() runs the receive half of the CAN cycle:
// it drains the channel into the master, advances the protocol clock, decodes every TPDO
// (statusword, position actual) and supervises the drives; write() runs the send half once per
// communication cycle (every cyclePeriod, which may span several servo periods): controlword and
// target of every RPDO, then SYNC. Axes run in CSP (0x607A from the position setpoint), the
// spindle in CSV or PV (0x60FF from the setpoint's change per cycle).
//
// Safety: a drive fault, an EMCY, a lost heartbeat, a missing TPDO, an unexpected NMT or drive
// state, a following error or bus off stops the set in the cycle that sees it: the cause reports
// Fault to motion, every node gets a quick-stop RPDO at once (the spindle ramps down too), and
// the records say which node and why. Only FaultReset clears it (lost nodes boot again).
//
// Constructed in the configuration thread; everything else is for the thread that runs the servo
// cycle: noexcept, no allocation, no locks, no clock reads.
namespace kerf::drivers::cia402 {

struct JointDrive {
    int node = -1;  // index into the master's nodes; -1: no drive (the joint echoes its setpoint)
    Mode mode = Mode::CyclicPosition;
    double countsPerUnit = 10000.0;     // drive position units per mm or degree
    double followingErrorWindow = 1.0;  // joint units; the master faults at twice it (0: off)
    // Byte offsets in RPDO1 / TPDO1.
    int rpdoControlword = 0;
    int rpdoTarget = 2;
    int tpdoStatusword = 0;
    int tpdoPosition = 2;
};

struct AdapterConfig {
    std::vector<JointDrive> joints;  // index = motion joint
    std::chrono::nanoseconds cyclePeriod{std::chrono::milliseconds(1)};
    std::chrono::nanoseconds enableStepTimeout{std::chrono::milliseconds(500)};
    std::vector<uint16_t> emcyWarnings;  // EMCY codes that only warn (statusword bit 7 style)
};

// Whether a drive stands still, as far as the master can tell from its TPDOs.
enum class Standstill : uint8_t {
    Moving,
    AtRest,   // the statusword says it stopped and the position stayed within one count
    Unknown,  // its TPDOs no longer arrive: the master cannot tell
};

class DriveBusAdapter final : public motion::DriveBus {
public:
    static constexpr size_t kMaxRecords = 32;
    // TPDOs in a row with the position within one count: at rest (10 ms at a 2 ms cycle).
    static constexpr int kRestTpdos = 5;

    DriveBusAdapter(canopen::Master& master, can::CanChannel& channel,
                    const canopen::ProtocolClock& clock, AdapterConfig config);

    int jointCount() const noexcept override { return static_cast<int>(m_joints.size()); }
    motion::BusResult read(std::span<motion::JointFeedback> feedback) noexcept override;
    motion::BusResult write(std::span<const motion::JointSetpoint> setpoints) noexcept override;
    void request(motion::DriveRequest request) noexcept override;
    void setPosition(int joint, double position) noexcept override;
    void armProbe(bool armed) noexcept override;

    // Every joint's drive follows its setpoint (the boot is over and the enable confirmed).
    bool allEnabled() const noexcept;
    bool stopped() const noexcept { return m_stopped; }
    // Stops and warnings in the order they happened (the first stop is the cause).
    size_t recordCount() const noexcept { return m_recordCount; }
    const StopRecord& record(size_t i) const noexcept { return m_records[i]; }
    const DriveAxis& axis(int joint) const noexcept {
        return m_joints[static_cast<size_t>(joint)].axis;
    }
    // Actual position of a joint in its units (drive feedback, homing offset applied).
    double position(int joint) const noexcept;
    // At rest: the drive reports a finished stop (quick stop active with bit 10, fault, power
    // off) or holds in operation enabled, and its position did not change for kRestTpdos TPDOs.
    Standstill standstill(int joint) const noexcept;
    uint64_t sendErrors() const noexcept { return m_sendErrors; }

private:
    struct Joint {
        JointDrive config;
        DriveAxis axis;
        uint64_t sequence = 0;  // last TPDO seen
        int32_t raw = 0;        // last position actual, drive counts
        int64_t counts = 0;     // unwrapped
        bool haveCounts = false;
        std::chrono::nanoseconds lastTpdo{0};
        int32_t restRaw = 0;  // where the position has stayed for stillTpdos TPDOs
        int stillTpdos = 0;
        double offset = 0.0;  // position = counts / countsPerUnit + offset
        double setpoint = 0.0;
        double sentSetpoint = 0.0;         // setpoint of the last RPDO (CSV velocity)
        int32_t target = 0;                // CSP target of the last RPDO
        std::array<int32_t, 4> targets{};  // by SYNC number, for the following-error check
        uint64_t handedOverAt = 0;  // SYNC count when the target started following the setpoint
        bool handedOver = false;
        bool following = false;  // followed the target at the previous TPDO
        bool expectTpdo = false;
        bool faulted = false;
        uint16_t faultCode = 0;
        uint16_t emcyCode = 0;
        uint8_t emcyRegister = 0;
    };

    void receive(std::chrono::nanoseconds now) noexcept;
    void handleEvents(std::chrono::nanoseconds now) noexcept;
    void supervise(Joint& j, int index, std::chrono::nanoseconds now) noexcept;
    void runCommunicationCycle(std::chrono::nanoseconds now) noexcept;
    void packRpdo(Joint& j) noexcept;
    void stop(StopRecord record, bool warningOnly = false) noexcept;
    void quickStopAll(std::chrono::nanoseconds now) noexcept;
    void flush() noexcept;
    int jointOfNode(size_t nodeIndex) const noexcept;
    StopRecord recordFor(StopReason reason, int joint, std::chrono::nanoseconds now) const noexcept;

    canopen::Master& m_master;
    can::CanChannel& m_channel;
    const canopen::ProtocolClock& m_clock;
    AdapterConfig m_config;
    std::vector<Joint> m_joints;
    std::array<int, canopen::Master::kMaxNodes> m_jointOfNode{};
    std::array<StopRecord, kMaxRecords> m_records{};
    size_t m_recordCount = 0;
    bool m_stopped = false;
    bool m_newStop = false;
    bool m_busOff = false;
    bool m_errorPassiveSeen = false;
    bool m_wroteSinceRead = true;
    uint64_t m_sendErrors = 0;
};

}  // namespace kerf::drivers::cia402
