// The master against a drive played by hand: every frame the drive sends is written here, so the
// master's side of the protocol is checked without the simulated drive.
#include "drivers/canopen/master.h"

#include <gtest/gtest.h>

#include "drivers/canopen/master_error.h"
#include "drivers/canopen/sdo_abort.h"
#include "tests/drivers/canopen/frames.h"

namespace kerf::drivers::canopen {
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;
using test::drain;
using test::frame;
using Frames = std::vector<std::string>;

MasterConfig oneNode() {
    MasterConfig c;
    c.masterNode = 127;
    c.heartbeatPeriod = 100ms;
    c.heartbeatTimeout = 250ms;
    c.cyclePeriod = 1ms;
    c.pdoLossCycles = 3;
    MasterNodeConfig n;
    n.id = 2;
    n.boot.expect({0x1000, 0}, 0x0192, 0xFFFF, MasterErrc::DeviceTypeMismatch);
    n.boot.write({0x1017, 0}, 100, 2);
    n.rpdo.cobId = 0x202;
    n.rpdo.add({0x6040, 0, 16});
    n.rpdo.add({0x607A, 0, 32});
    n.tpdo.cobId = 0x182;
    n.tpdo.add({0x6041, 0, 16});
    n.tpdo.add({0x6064, 0, 32});
    c.nodes.push_back(std::move(n));
    return c;
}

class MasterTest : public testing::Test {
protected:
    void feed(const std::string& f, nanoseconds now) {
        master.onFrame(frame(f), now);
        master.advance(now);
    }
    std::vector<MasterEvent> events() {
        std::vector<MasterEvent> list;
        MasterEvent e;
        while (master.popEvent(e))
            list.push_back(e);
        return list;
    }
    // Boot as CiA 301/402 A2.4 has it; the node is operational at 12.5 ms.
    void boot() {
        master.start(0ms);
        master.advance(0ms);
        ASSERT_EQ(drain(master.outbox()), Frames{"000#8202"});  // reset communication, node 2
        EXPECT_EQ(master.phase(0), NodePhase::Resetting);
        feed("702#00", 10ms);  // boot-up
        ASSERT_EQ(drain(master.outbox()), Frames{"602#4000100000000000"});
        feed("582#4300100092010200", 11ms);
        ASSERT_EQ(drain(master.outbox()), Frames{"602#2B17100064000000"});
        feed("582#6017100000000000", 12ms);
        // All nodes configured: SYNC starts and the node gets the start command.
        ASSERT_EQ(drain(master.outbox()), Frames{"000#0102"});
        EXPECT_EQ(master.phase(0), NodePhase::Starting);
        EXPECT_EQ(master.bootValue(0, 0), 0x00020192u);
        master.produceCycle(12ms);
        ASSERT_EQ(drain(master.outbox()), (Frames{"202#000000000000", "080#"}));
        feed("182#370210270000", nanoseconds(12500us));
        ASSERT_EQ(master.phase(0), NodePhase::Operational);
        std::vector<MasterEvent> e = events();
        ASSERT_EQ(e.size(), 2u);
        EXPECT_EQ(e[0].kind, MasterEventKind::Configured);
        EXPECT_EQ(e[1].kind, MasterEventKind::Operational);
        EXPECT_EQ(master.tpdo(0).sequence, 1u);
        EXPECT_EQ(master.tpdo(0).length, 6);
    }
    Master master{oneNode()};
};

TEST_F(MasterTest, BootsConfiguresAndStartsANode) {
    boot();
}

TEST_F(MasterTest, CyclicExchangeCarriesTheRpdoTheOwnerFilled) {
    boot();
    std::span<uint8_t> rpdo = master.rpdo(0);
    ASSERT_EQ(rpdo.size(), 6u);
    packField(rpdo, 0, 2, 0x000F);
    packField(rpdo, 2, 4, 12345);
    EXPECT_FALSE(master.cycleDue(nanoseconds(12900us)));
    master.produceCycle(nanoseconds(12900us));
    EXPECT_TRUE(drain(master.outbox()).empty());
    ASSERT_TRUE(master.cycleDue(13ms));
    master.produceCycle(13ms);
    EXPECT_EQ(drain(master.outbox()), (Frames{"202#0F0039300000", "080#"}));
}

// TPDOs for the SYNCs of 13, 14 and 15 ms never come: producing the SYNC of 16 ms finds three
// cycles without the node's TPDO.
TEST_F(MasterTest, MissingTpdoIsDetectedAfterTheConfiguredCycles) {
    boot();
    for (int ms = 13; ms <= 15; ++ms) {
        master.produceCycle(std::chrono::milliseconds(ms));
        EXPECT_TRUE(events().empty()) << ms;
    }
    master.produceCycle(16ms);
    std::vector<MasterEvent> e = events();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].kind, MasterEventKind::PdoMissing);
    EXPECT_EQ(e[0].node, 2);
    EXPECT_EQ(e[0].time, 16ms);
    EXPECT_EQ(e[0].error, MasterErrc::PdoMissing);
    EXPECT_EQ(master.phase(0), NodePhase::Lost);
}

TEST_F(MasterTest, OneLateTpdoIsNoLoss) {
    boot();
    master.produceCycle(13ms);
    master.produceCycle(14ms);
    feed("182#370210270000", nanoseconds(14500us));
    master.produceCycle(15ms);
    master.produceCycle(16ms);
    EXPECT_TRUE(events().empty());
    EXPECT_EQ(master.phase(0), NodePhase::Operational);
}

// Consumer time 250 ms, counted from the start command (12 ms) or the last heartbeat.
TEST_F(MasterTest, LostHeartbeatIsDetectedAfterTheConsumerTime) {
    boot();
    feed("702#05", 100ms);
    master.advance(350ms);
    EXPECT_TRUE(events().empty());
    master.advance(351ms);
    std::vector<MasterEvent> e = events();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].kind, MasterEventKind::HeartbeatLost);
    EXPECT_EQ(e[0].error, MasterErrc::HeartbeatLost);
    EXPECT_EQ(master.phase(0), NodePhase::Lost);
}

TEST_F(MasterTest, ANodeThatFallsBackToPreOperationalIsLost) {
    boot();
    feed("702#7F", 50ms);
    std::vector<MasterEvent> e = events();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].kind, MasterEventKind::UnexpectedState);
    EXPECT_EQ(e[0].state, NmtState::PreOperational);
}

TEST_F(MasterTest, EmergencyIsReportedWithItsCode) {
    boot();
    feed("082#1086210000000000", 20ms);
    std::vector<MasterEvent> e = events();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].kind, MasterEventKind::Emergency);
    EXPECT_EQ(e[0].emcy.code, 0x8610);
    EXPECT_EQ(e[0].emcy.errorRegister, 0x21);
}

TEST_F(MasterTest, MasterSendsItsOwnHeartbeat) {
    boot();
    master.advance(100ms);
    EXPECT_EQ(drain(master.outbox()), Frames{"77F#05"});
}

TEST_F(MasterTest, NoBootUpWithinTheTimeout) {
    master.start(0ms);
    master.advance(5000ms);
    EXPECT_TRUE(events().empty());
    master.advance(5001ms);
    std::vector<MasterEvent> e = events();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].kind, MasterEventKind::BootFailed);
    EXPECT_EQ(e[0].error, MasterErrc::BootUpTimeout);
    EXPECT_EQ(master.phase(0), NodePhase::Failed);
}

TEST_F(MasterTest, WrongDeviceTypeFailsTheBoot) {
    master.start(0ms);
    feed("702#00", 10ms);
    drain(master.outbox());
    feed("582#4300100091010200", 11ms);  // profile 0x0191, not 402
    std::vector<MasterEvent> e = events();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].kind, MasterEventKind::BootFailed);
    EXPECT_EQ(e[0].error, MasterErrc::DeviceTypeMismatch);
    EXPECT_EQ(e[0].object, (ObjectAddress{0x1000, 0}));
    EXPECT_TRUE(drain(master.outbox()).empty()) << "no further steps, no start";
}

TEST_F(MasterTest, SdoAbortFailsTheBootWithTheAbortCode) {
    master.start(0ms);
    feed("702#00", 10ms);
    feed("582#4300100092010200", 11ms);
    drain(master.outbox());
    feed("582#8017100000000606", 12ms);  // 0x06060000 hardware error
    std::vector<MasterEvent> e = events();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].error, SdoAbort::HardwareError);
    EXPECT_EQ(e[0].object, (ObjectAddress{0x1017, 0}));
}

TEST_F(MasterTest, RestartBootsALostNodeAgain) {
    boot();
    master.produceCycle(13ms);
    master.produceCycle(14ms);
    master.produceCycle(15ms);
    master.produceCycle(16ms);
    drain(master.outbox());
    ASSERT_EQ(master.phase(0), NodePhase::Lost);
    master.restartNode(0, 20ms);
    EXPECT_EQ(drain(master.outbox()), Frames{"000#8202"});
    feed("702#00", 30ms);
    EXPECT_EQ(drain(master.outbox()), Frames{"602#4000100000000000"});
}

TEST(MasterConfigErrors, RejectsDuplicateOrInvalidNodeIds) {
    MasterConfig c = oneNode();
    c.nodes.push_back(c.nodes.front());
    EXPECT_THROW(Master{c}, std::invalid_argument);
    MasterConfig master = oneNode();
    master.nodes.front().id = 127;  // the master's own heartbeat
    EXPECT_THROW(Master{master}, std::invalid_argument);
}

}  // namespace
}  // namespace kerf::drivers::canopen
