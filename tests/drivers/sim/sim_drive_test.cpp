// The simulated drive as a CANopen node: the test plays the master with raw frames and an SDO
// client on a virtual bus, and checks the answers against CiA 301/402.
#include "drivers/sim/sim_drive.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/can/virtual_bus.h"
#include "drivers/canopen/emcy.h"
#include "drivers/canopen/sdo_abort.h"
#include "drivers/canopen/sdo_client.h"
#include "tests/drivers/canopen/frames.h"

namespace kerf::drivers::sim {
namespace {

using namespace std::chrono_literals;
using canopen::SdoAbort;
using canopen::SdoStatus;
using cia402::State;
using std::chrono::nanoseconds;
using test::frame;
using test::text;

class SimDriveTest : public testing::Test {
protected:
    SimDriveTest()
        : master(bus.attach("master")), channel(bus.attach("drive")), drive(config(), channel) {
        client.configure(1, 100ms);
        drive.powerOn(0ms);
        run(20ms);
    }
    static SimDriveConfig config() {
        SimDriveConfig c;
        c.node = 1;
        c.plant.maxVelocity = 1e6;
        c.plant.maxAcceleration = 1e7;
        return c;
    }
    // Runs bus and drive event by event up to `until`; the master's frames go into `received`.
    void run(nanoseconds until) {
        flush();
        step(now);
        for (int guard = 0; guard < 100000 && now < until; ++guard) {
            nanoseconds t = until;
            if (auto d = bus.nextDelivery()) t = std::min(t, std::max(*d, now));
            nanoseconds deadline = drive.nextDeadline();
            if (deadline > now) t = std::min(t, deadline);
            step(t);
        }
    }
    void step(nanoseconds t) {
        bus.advanceTo(t);
        now = t;
        drive.poll(now);
        can::CanFrame f;
        while (master.receive(f)) {
            received.push_back(text(f));
            if (f.id == 0x581) client.onFrame(f, now, out);
        }
        client.advance(now, out);
        flush();
    }
    void flush() {
        while (!out.empty()) {
            master.send(out.front());
            out.pop();
        }
    }
    void send(const std::string& f) {
        master.send(frame(f));
        run(now + 1ms);
    }
    std::error_code write(canopen::ObjectAddress a, std::vector<uint8_t> bytes) {
        client.acknowledge();
        EXPECT_TRUE(client.download(a, bytes, now, out));
        run(now + 5ms);
        EXPECT_NE(client.status(), SdoStatus::Busy);
        return client.status() == SdoStatus::Failed ? client.error() : std::error_code();
    }
    std::error_code read(canopen::ObjectAddress a) {
        client.acknowledge();
        EXPECT_TRUE(client.upload(a, now, out));
        run(now + 5ms);
        EXPECT_NE(client.status(), SdoStatus::Busy);
        return client.status() == SdoStatus::Failed ? client.error() : std::error_code();
    }
    // The statusword of the last TPDO1 (default mapping: statusword only, sent on change).
    uint16_t lastStatusword() const {
        for (auto it = received.rbegin(); it != received.rend(); ++it) {
            if (it->rfind("181#", 0) == 0)
                return static_cast<uint16_t>(
                    std::stoul(it->substr(6, 2) + it->substr(4, 2), nullptr, 16));
        }
        return 0xFFFF;
    }
    State lastState() const {
        State s = State::NotReadyToSwitchOn;
        EXPECT_TRUE(cia402::decodeStatusword(lastStatusword(), s));
        return s;
    }
    bool receivedFrame(const std::string& f) const {
        return std::find(received.begin(), received.end(), f) != received.end();
    }

    can::VirtualBus bus{1'000'000};
    can::VirtualChannel& master;
    can::VirtualChannel& channel;
    SimDrive drive;
    canopen::SdoClient client;
    canopen::FrameOutbox out;
    nanoseconds now{0};
    std::vector<std::string> received;
};

TEST_F(SimDriveTest, BootsIntoPreOperationalWithABootUpMessage) {
    EXPECT_EQ(received, std::vector<std::string>{"701#00"});
    EXPECT_EQ(drive.nmtState(), canopen::NmtState::PreOperational);
    EXPECT_EQ(drive.state(), State::SwitchOnDisabled);  // transitions 0 and 1
}

TEST_F(SimDriveTest, AnswersExpeditedAndSegmentedUploads) {
    ASSERT_FALSE(read({0x1000, 0}));
    EXPECT_EQ(client.value(), 0x00020192u);
    ASSERT_FALSE(read({0x1018, 1}));
    EXPECT_EQ(client.value(), kSimVendorId);
    ASSERT_FALSE(read({0x6502, 0}));
    EXPECT_EQ(client.value(), 0x184u) << "PV, CSP, CSV";
    ASSERT_FALSE(read({0x1008, 0}));
    EXPECT_EQ(std::string(client.data().begin(), client.data().end()),
              "Kerf simulated servo drive");
    EXPECT_TRUE(receivedFrame("581#410810001A000000")) << "segmented: size 26 announced";
}

TEST_F(SimDriveTest, SegmentedDownloadIsStoredAndReadBack) {
    std::string text = "a string longer than four bytes";
    ASSERT_FALSE(write({0x2001, 0}, std::vector<uint8_t>(text.begin(), text.end())));
    ASSERT_FALSE(read({0x2001, 0}));
    EXPECT_EQ(std::string(client.data().begin(), client.data().end()), text);
    std::string tooLong(49, 'x');  // the object holds 48 bytes
    EXPECT_EQ(write({0x2001, 0}, std::vector<uint8_t>(tooLong.begin(), tooLong.end())),
              SdoAbort::LengthTooHigh);
}

TEST_F(SimDriveTest, AbortsWithTheStandardCodes) {
    EXPECT_EQ(write({0x1000, 0}, {1, 0, 0, 0}), SdoAbort::WriteOfReadOnly);
    EXPECT_EQ(read({0x1234, 0}), SdoAbort::NoObject);
    EXPECT_EQ(read({0x1018, 7}), SdoAbort::NoSubIndex);
    EXPECT_EQ(write({0x1017, 0}, {100, 0, 0, 0}), SdoAbort::LengthMismatch) << "UNSIGNED16";
    EXPECT_EQ(write({0x6060, 0}, {5}), SdoAbort::InvalidValue) << "mode 5 is not in 0x6502";
    EXPECT_EQ(write({0x605A, 0}, {3, 0}), SdoAbort::InvalidValue);
    // PDO mapping: entries only while sub-index 0 is 0 and the PDO is invalid; mappable objects.
    EXPECT_EQ(write({0x1A00, 1}, {0x10, 0, 0x41, 0x60}), SdoAbort::DeviceState) << "TPDO1 valid";
    ASSERT_FALSE(write({0x1800, 1}, {0x81, 0x01, 0, 0x80}));
    EXPECT_EQ(write({0x1A00, 1}, {0x10, 0, 0x41, 0x60}), SdoAbort::DeviceState) << "sub 0 is 1";
    ASSERT_FALSE(write({0x1A00, 0}, {0}));
    EXPECT_EQ(write({0x1A00, 1}, {0x20, 0, 0x00, 0x10}), SdoAbort::NotMappable) << "0x1000";
    EXPECT_EQ(write({0x1A00, 1}, {0x20, 0, 0x7A, 0x60}), SdoAbort::NotMappable) << "an RPDO object";
    EXPECT_EQ(write({0x1A00, 1}, {0x10, 0, 0x64, 0x60}), SdoAbort::NotMappable)
        << "length 16 of 32";
    for (uint8_t sub = 1; sub <= 3; ++sub) {
        ASSERT_FALSE(write({0x1A00, sub}, {0x20, 0, 0x64, 0x60}));
    }
    EXPECT_EQ(write({0x1A00, 0}, {3}), SdoAbort::MappingTooLong) << "96 bits";
    EXPECT_EQ(write({0x1A00, 0}, {9}), SdoAbort::ValueTooHigh);
    ASSERT_FALSE(write({0x1A00, 0}, {2}));
}

TEST_F(SimDriveTest, RefusesRemappingInOperational) {
    send("000#0101");
    ASSERT_EQ(drive.nmtState(), canopen::NmtState::Operational);
    EXPECT_EQ(write({0x1800, 1}, {0x81, 0x01, 0, 0x80}), SdoAbort::DeviceState);
    EXPECT_EQ(write({0x1600, 0}, {0}), SdoAbort::DeviceState);
}

TEST_F(SimDriveTest, InjectedAbortAndIdentity) {
    drive.injectSdoAbort({0x1017, 0}, 0x06060000);
    EXPECT_EQ(write({0x1017, 0}, {100, 0}), SdoAbort::HardwareError);
    EXPECT_EQ(read({0x1017, 0}), SdoAbort::HardwareError);
    drive.setIdentity(0x1234, 0x99);
    ASSERT_FALSE(read({0x1018, 2}));
    EXPECT_EQ(client.value(), 0x99u);
}

TEST_F(SimDriveTest, HeartbeatProducerAndNmtStates) {
    ASSERT_FALSE(write({0x1017, 0}, {100, 0}));
    received.clear();
    run(now + 100ms);
    EXPECT_EQ(received, std::vector<std::string>{"701#7F"});
    send("000#0100");  // start every node
    received.clear();
    run(now + 100ms);
    EXPECT_EQ(received, std::vector<std::string>{"701#05"});
    send("000#0201");  // stop: only NMT and heartbeat
    EXPECT_EQ(drive.nmtState(), canopen::NmtState::Stopped);
    received.clear();
    master.send(frame("601#4000100000000000"));
    run(now + 100ms);
    EXPECT_EQ(received, std::vector<std::string>{"701#04"}) << "no SDO answer in Stopped";
    send("000#8101");  // reset node: boot-up again after the boot time
    run(now + 20ms);
    EXPECT_TRUE(receivedFrame("701#00"));
}

TEST_F(SimDriveTest, StopsItsHeartbeatOrFallsSilentOnRequest) {
    ASSERT_FALSE(write({0x1017, 0}, {10, 0}));
    drive.stopHeartbeat();
    received.clear();
    run(now + 50ms);
    EXPECT_TRUE(received.empty());
    drive.goSilent();
    master.send(frame("601#4000100000000000"));
    run(now + 10ms);
    EXPECT_TRUE(received.empty());
}

// The drive watches the master's heartbeat (0x1016) once it has seen one; when it stops, the drive
// sends EMCY 0x8130 and reacts as 0x6007 says (1: fault).
TEST_F(SimDriveTest, LostMasterHeartbeatIsADriveFault) {
    ASSERT_FALSE(write({0x1016, 1}, {0xFA, 0x00, 0x7F, 0x00}));  // node 127, 250 ms
    ASSERT_FALSE(write({0x6007, 0}, {1, 0}));
    send("000#0101");
    for (int i = 0; i < 3; ++i) {
        master.send(frame("77F#05"));
        run(now + (i < 2 ? 100ms : 1ms));
    }
    received.clear();
    run(now + 200ms);
    EXPECT_TRUE(received.empty()) << "within the consumer time";
    run(now + 60ms);
    ASSERT_FALSE(received.empty());
    EXPECT_EQ(received.front(), "081#3081110000000000");
    EXPECT_EQ(drive.state(), State::Fault);
    EXPECT_EQ(drive.errorCode(), 0x8130);
}

// Every transition of A2.3, commanded by RPDO1 (default mapping: controlword, event-driven,
// applied at once) and confirmed by TPDO1 (statusword, sent on change).
TEST_F(SimDriveTest, EveryTransitionOfTheStateMachine) {
    send("000#0101");
    auto command = [this](const char* controlword) {
        send(std::string("201#") + controlword);
        return lastState();
    };
    EXPECT_EQ(lastState(), State::SwitchOnDisabled);
    EXPECT_EQ(command("0600"), State::ReadyToSwitchOn);   // 2
    EXPECT_EQ(command("0700"), State::SwitchedOn);        // 3
    EXPECT_EQ(command("0F00"), State::OperationEnabled);  // 4
    EXPECT_EQ(command("0700"), State::SwitchedOn);        // 5
    EXPECT_EQ(command("0600"), State::ReadyToSwitchOn);   // 6
    EXPECT_EQ(command("0000"), State::SwitchOnDisabled);  // 7 (disable voltage)
    command("0600");
    EXPECT_EQ(command("0200"), State::SwitchOnDisabled);  // 7 (quick stop)
    command("0600");
    command("0700");
    EXPECT_EQ(command("0000"), State::SwitchOnDisabled);  // 10 (disable voltage)
    command("0600");
    command("0700");
    EXPECT_EQ(command("0200"), State::SwitchOnDisabled);  // 10 (quick stop)
    command("0600");
    command("0700");
    command("0F00");
    EXPECT_EQ(command("0600"), State::ReadyToSwitchOn);  // 8
    command("0700");
    command("0F00");
    EXPECT_EQ(command("0000"), State::SwitchOnDisabled);  // 9
    EXPECT_EQ(command("0F00"), State::SwitchOnDisabled) << "0x0F is not the Shutdown pattern";
    // Quick stop with 0x605A = 6: ramp, then stay; 16 back to operation; 12 to switch on disabled.
    ASSERT_FALSE(write({0x605A, 0}, {6, 0}));
    command("0600");
    command("0700");
    command("0F00");
    EXPECT_EQ(command("0B00"), State::QuickStopActive);  // 11
    run(now + 10ms);
    EXPECT_EQ(lastState(), State::QuickStopActive);
    EXPECT_EQ(command("0F00"), State::OperationEnabled);  // 16
    command("0B00");
    EXPECT_EQ(command("0000"), State::SwitchOnDisabled);  // 12 (disable voltage)
    // With 0x605A = 2 the drive ends the quick stop in switch on disabled by itself (12).
    ASSERT_FALSE(write({0x605A, 0}, {2, 0}));
    command("0600");
    command("0700");
    command("0F00");
    command("0B00");
    run(now + 10ms);
    EXPECT_EQ(lastState(), State::SwitchOnDisabled);
    EXPECT_EQ(command("0F00"), State::SwitchOnDisabled) << "no 16 with 0x605A = 2";
    // 13 and 14: a fault, EMCY first, fault reaction, then Fault.
    command("0600");
    command("0700");
    command("0F00");
    received.clear();
    drive.injectFault(0x4310, now);
    run(now + 10ms);
    ASSERT_FALSE(received.empty());
    EXPECT_EQ(received.front(), "081#1043090000000000");
    EXPECT_EQ(lastState(), State::Fault);
    EXPECT_EQ(command("0600"), State::Fault) << "only the reset leaves Fault";
    // 15: the rising edge of bit 7; the drive clears its error with EMCY 0x0000.
    EXPECT_EQ(command("0000"), State::Fault);
    received.clear();
    EXPECT_EQ(command("8000"), State::SwitchOnDisabled);
    EXPECT_TRUE(receivedFrame("081#0000000000000000"));
    EXPECT_EQ(drive.errorCode(), 0);
}

TEST_F(SimDriveTest, EncoderLossCannotBeReset) {
    send("000#0101");
    drive.injectEncoderLoss(now);
    run(now + 5ms);
    EXPECT_TRUE(receivedFrame("081#0573010000000000"));
    EXPECT_EQ(lastState(), State::Fault);
    send("201#0000");
    send("201#8000");
    EXPECT_EQ(lastState(), State::Fault);
    EXPECT_EQ(drive.errorCode(), 0x7305);
}

// A synchronous RPDO (type 1) is latched and applied at the next SYNC (A2.1); a synchronous
// TPDO goes out after each SYNC.
TEST_F(SimDriveTest, SynchronousPdosActAtTheSync) {
    ASSERT_FALSE(write({0x1400, 1}, {0x01, 0x02, 0x00, 0x80}));
    ASSERT_FALSE(write({0x1400, 2}, {1}));
    ASSERT_FALSE(write({0x1400, 1}, {0x01, 0x02, 0x00, 0x00}));
    ASSERT_FALSE(write({0x1800, 1}, {0x81, 0x01, 0x00, 0x80}));
    ASSERT_FALSE(write({0x1800, 2}, {1}));
    ASSERT_FALSE(write({0x1800, 1}, {0x81, 0x01, 0x00, 0x00}));
    send("000#0101");
    received.clear();
    send("201#0600");
    EXPECT_TRUE(received.empty()) << "latched, no TPDO without SYNC";
    EXPECT_EQ(drive.state(), State::SwitchOnDisabled);
    send("080#");
    EXPECT_EQ(drive.state(), State::ReadyToSwitchOn);
    EXPECT_EQ(received, std::vector<std::string>{"181#3102"});
    send("080#");
    EXPECT_EQ(received.size(), 2u) << "one TPDO per SYNC";
}

}  // namespace
}  // namespace kerf::drivers::sim
