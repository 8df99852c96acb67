#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string_view>

#include "drivers/can/can_channel.h"
#include "drivers/canopen/frame_outbox.h"
#include "drivers/canopen/heartbeat.h"
#include "drivers/canopen/nmt.h"
#include "drivers/cia402/state_machine.h"
#include "drivers/sim/object_dictionary.h"
#include "drivers/sim/sdo_server.h"
#include "drivers/sim/servo_plant.h"

// A simulated CiA 402 servo drive that is a real node on a CAN channel: NMT slave with boot-up
// message, object dictionary with SDO server, configurable PDOs (synchronous RPDOs applied at the
// next SYNC, TPDOs sent on SYNC or on change), heartbeat producer and consumer (0x1017/0x1016,
// reaction 0x6007), EMCY producer, the CiA 402 state machine from the shared table with quick
// stop (0x605A) and fault reaction, modes CSP, CSV and PV, a servo plant with following-error
// monitoring (0x6065/0x6066 -> Fault 0x8611) and software position limits (0x607D).
//
// Fault injection for tests: a fault with any EMCY code, a following error (the axis is pushed
// away while it is driven in Operation enabled), encoder loss, heartbeat loss, a drive that falls
// silent, TPDOs that stop, slow boot, wrong identity, SDO aborts on an object.
//
// Passive like the master: poll(now) takes the received frames, runs timers and the plant up to
// `now` and sends; nextDeadline() tells an event-driven simulation when to poll next. The
// constructor allocates; poll() does not. Simulation thread only.
namespace kerf::drivers::sim {

// Identity of the simulated drive (0x1018). The vendor-ID is not one CiA assigned.
inline constexpr uint32_t kSimVendorId = 0x4B455246;  // "KERF"
inline constexpr uint32_t kSimProductCode = 0x00000402;
inline constexpr uint32_t kSimRevision = 0x00010000;
inline constexpr uint32_t kSimDeviceType = 0x00020192;  // CiA 402, servo drive
// Supported drive modes (0x6502): PV (bit 2), CSP (bit 7), CSV (bit 8).
inline constexpr uint32_t kSimSupportedModes = 1u << 2 | 1u << 7 | 1u << 8;

struct SimDriveConfig {
    uint8_t node = 1;
    uint32_t vendorId = kSimVendorId;
    uint32_t productCode = kSimProductCode;
    uint32_t revision = kSimRevision;
    uint32_t serial = 1;
    std::string_view deviceName = "Kerf simulated servo drive";
    PlantParameters plant;
    double initialPosition = 0.0;  // counts
    std::chrono::nanoseconds bootTime{std::chrono::milliseconds(10)};
};

class SimDrive final : private SdoServerHooks {
public:
    SimDrive(const SimDriveConfig& config, can::CanChannel& channel);

    // Where the axis stands at power-on (counts); before powerOn().
    void setInitialPosition(double counts) noexcept { m_plant.reset(counts); }
    // Power-up: the node boots (boot-up message after bootTime).
    void powerOn(std::chrono::nanoseconds now) noexcept;
    void poll(std::chrono::nanoseconds now) noexcept;
    std::chrono::nanoseconds nextDeadline() const noexcept;

    uint8_t node() const noexcept { return m_node; }
    bool booted() const noexcept { return !m_booting && m_powered; }
    canopen::NmtState nmtState() const noexcept { return m_nmt; }
    cia402::State state() const noexcept { return m_state; }
    uint16_t statusword() const noexcept;
    double position() const noexcept { return m_plant.position(); }  // counts, unwrapped
    const ServoPlant& plant() const noexcept { return m_plant; }
    const ObjectDictionary& dictionary() const noexcept { return m_od; }
    uint16_t errorCode() const noexcept;  // 0x603F

    // Fault injection.
    void injectFault(uint16_t emcyCode, std::chrono::nanoseconds now) noexcept;
    void injectEmcyWarning(uint16_t emcyCode) noexcept;
    void injectFollowingError(double driftCountsPerS) noexcept {
        m_plant.setDrift(driftCountsPerS);
    }
    void injectEncoderLoss(std::chrono::nanoseconds now) noexcept;
    void stopHeartbeat() noexcept { m_heartbeatStopped = true; }
    void goSilent() noexcept;
    void stopTpdos() noexcept { m_tpdosStopped = true; }
    void setBootTime(std::chrono::nanoseconds bootTime) noexcept { m_bootTime = bootTime; }
    void setIdentity(uint32_t vendorId, uint32_t productCode) noexcept;
    void injectSdoAbort(ObjectAddress address, uint32_t abortCode) noexcept;

private:
    static constexpr int kPdoCount = 4;
    struct Rpdo {
        std::array<uint8_t, 8> data{};
        uint8_t length = 0;
        bool latched = false;
    };
    struct Tpdo {
        std::array<uint8_t, 8> lastSent{};
        std::chrono::nanoseconds lastTime{0};
        bool sentOnce = false;
    };

    void buildDictionary(const SimDriveConfig& config);
    void resetCommunication() noexcept;
    void finishBoot(std::chrono::nanoseconds now) noexcept;
    void onFrame(const can::CanFrame& frame, std::chrono::nanoseconds now) noexcept;
    void onNmt(const can::CanFrame& frame, std::chrono::nanoseconds now) noexcept;
    void onSync(std::chrono::nanoseconds now) noexcept;
    void applyRpdo(int number, const Rpdo& rpdo, std::chrono::nanoseconds now) noexcept;
    void processControlword(uint16_t controlword, std::chrono::nanoseconds now) noexcept;
    void enterState(cia402::State state, std::chrono::nanoseconds now) noexcept;
    void applyTargets() noexcept;
    void sample() noexcept;
    size_t packTpdo(int number, std::array<uint8_t, 8>& data) const noexcept;
    void sendTpdo(int number, std::chrono::nanoseconds now) noexcept;
    void runTimers(std::chrono::nanoseconds now) noexcept;
    void emcy(uint16_t code) noexcept;
    void send(const can::CanFrame& frame) noexcept;
    double interpolationPeriodS() const noexcept;
    uint32_t tpdoCobId(int number) const noexcept;
    uint32_t rpdoCobId(int number) const noexcept;

    // SdoServerHooks
    uint32_t accessAbort(ObjectAddress address) noexcept override;
    uint32_t checkWrite(const ObjectEntry& entry, std::span<const uint8_t> bytes) noexcept override;
    void written(const ObjectEntry& entry) noexcept override;

    uint8_t m_node;
    can::CanChannel& m_channel;
    ObjectDictionary m_od;
    SdoServer m_sdo;
    ServoPlant m_plant;
    canopen::HeartbeatProducer m_heartbeat;
    canopen::HeartbeatConsumer m_consumer;
    canopen::FrameOutbox m_outbox;
    std::array<Rpdo, kPdoCount> m_rpdo{};
    std::array<Tpdo, kPdoCount> m_tpdo{};

    bool m_powered = false;
    bool m_booting = false;
    std::chrono::nanoseconds m_bootTime;
    std::chrono::nanoseconds m_bootAt{0};
    std::chrono::nanoseconds m_now{0};  // plant time
    canopen::NmtState m_nmt = canopen::NmtState::BootUp;
    cia402::State m_state = cia402::State::NotReadyToSwitchOn;
    uint16_t m_lastControlword = 0;
    uint64_t m_syncs = 0;
    bool m_limitActive = false;
    bool m_followingErrorActive = false;
    std::chrono::nanoseconds m_followingErrorSince{0};
    bool m_encoderLost = false;
    int32_t m_frozenPosition = 0;
    bool m_heartbeatStopped = false;
    bool m_silent = false;
    bool m_tpdosStopped = false;
    can::ControllerState m_controller = can::ControllerState::ErrorActive;
    ObjectAddress m_abortAddress;
    uint32_t m_abortCode = 0;
};

}  // namespace kerf::drivers::sim
