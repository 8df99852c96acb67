// NMT, heartbeat, EMCY, SYNC, PDO mapping and the bus-load budget: frame bytes and figures from
// CiA 301 and the spec.
#include <gtest/gtest.h>

#include "drivers/canopen/bus_load.h"
#include "drivers/canopen/emcy.h"
#include "drivers/canopen/heartbeat.h"
#include "drivers/canopen/nmt.h"
#include "drivers/canopen/pdo.h"
#include "drivers/canopen/sync_producer.h"
#include "tests/drivers/canopen/frames.h"

namespace kerf::drivers::canopen {
namespace {

using namespace std::chrono_literals;
using test::drain;
using test::frame;
using test::text;
using Frames = std::vector<std::string>;

TEST(Nmt, CommandFrames) {
    EXPECT_EQ(text(nmtFrame(NmtCommand::Start, 1)), "000#0101");
    EXPECT_EQ(text(nmtFrame(NmtCommand::Stop, 2)), "000#0202");
    EXPECT_EQ(text(nmtFrame(NmtCommand::EnterPreOperational, 0)), "000#8000");
    EXPECT_EQ(text(nmtFrame(NmtCommand::ResetNode, 3)), "000#8103");
    EXPECT_EQ(text(nmtFrame(NmtCommand::ResetCommunication, 4)), "000#8204");
}

TEST(Nmt, HeartbeatStates) {
    uint8_t node = 0;
    NmtState state{};
    ASSERT_TRUE(parseHeartbeat(frame("701#00"), node, state));
    EXPECT_EQ(node, 1);
    EXPECT_EQ(state, NmtState::BootUp);
    ASSERT_TRUE(parseHeartbeat(frame("77F#05"), node, state));
    EXPECT_EQ(node, 127);
    EXPECT_EQ(state, NmtState::Operational);
    ASSERT_TRUE(parseHeartbeat(frame("703#7F"), node, state));
    EXPECT_EQ(state, NmtState::PreOperational);
    ASSERT_TRUE(parseHeartbeat(frame("703#04"), node, state));
    EXPECT_EQ(state, NmtState::Stopped);
    EXPECT_FALSE(parseHeartbeat(frame("703#06"), node, state));    // no such state
    EXPECT_FALSE(parseHeartbeat(frame("703#0500"), node, state));  // one byte only
    EXPECT_FALSE(parseHeartbeat(frame("603#05"), node, state));
    EXPECT_EQ(text(heartbeatFrame(4, NmtState::Operational)), "704#05");
}

TEST(Heartbeat, ProducerSendsEveryPeriod) {
    HeartbeatProducer p;
    FrameOutbox out;
    p.configure(127, 100ms, 0ms);
    p.advance(99ms, NmtState::Operational, out);
    EXPECT_TRUE(drain(out).empty());
    p.advance(100ms, NmtState::Operational, out);
    EXPECT_EQ(drain(out), Frames{"77F#05"});
    p.advance(150ms, NmtState::Operational, out);
    EXPECT_TRUE(drain(out).empty());
    p.advance(200ms, NmtState::PreOperational, out);
    EXPECT_EQ(drain(out), Frames{"77F#7F"});
    p.advance(1000ms, NmtState::Operational, out);  // late: one frame, not eight
    EXPECT_EQ(drain(out).size(), 1u);
}

// 0x1016 entries: node-ID in bits 16-23, time in ms in bits 0-15.
TEST(Heartbeat, ConsumerDetectsTheTimeout) {
    EXPECT_EQ(heartbeatConsumerEntry(3, 250), 0x000300FAu);
    HeartbeatConsumer c;
    ASSERT_TRUE(c.configure(0, 0x000300FA));
    EXPECT_EQ(c.entryValue(0), 0x000300FAu);
    c.arm(3, 0ms);
    EXPECT_EQ(c.nextTimeout(250ms), nullptr);
    c.onHeartbeat(3, NmtState::Operational, 100ms);
    EXPECT_EQ(c.nextTimeout(350ms), nullptr);  // exactly the consumer time: not yet
    const HeartbeatConsumer::Entry* lost = c.nextTimeout(351ms);
    ASSERT_NE(lost, nullptr);
    EXPECT_EQ(lost->node, 3);
    EXPECT_EQ(c.nextTimeout(400ms), nullptr) << "reported once";
    c.arm(3, 400ms);
    EXPECT_EQ(c.nextTimeout(600ms), nullptr);
    EXPECT_NE(c.nextTimeout(651ms), nullptr) << "a node that never speaks is caught too";
}

TEST(Heartbeat, UnarmedOrUnknownNodesAreNotWatched) {
    HeartbeatConsumer c;
    c.configure(0, heartbeatConsumerEntry(5, 100));
    EXPECT_EQ(c.nextTimeout(10s), nullptr);
    EXPECT_EQ(c.onHeartbeat(6, NmtState::Operational, 0ms), nullptr);
}

TEST(Emcy, DecodesCodeRegisterAndManufacturerData) {
    uint8_t node = 0;
    Emcy e;
    ASSERT_TRUE(parseEmcy(frame("082#1186210102030405"), node, e));
    EXPECT_EQ(node, 2);
    EXPECT_EQ(e.code, 0x8611);
    EXPECT_EQ(e.errorRegister, 0x21);
    EXPECT_EQ(e.manufacturer, (std::array<uint8_t, 5>{1, 2, 3, 4, 5}));
    EXPECT_FALSE(parseEmcy(frame("080#"), node, e)) << "SYNC, not an EMCY";
    EXPECT_FALSE(parseEmcy(frame("082#1186"), node, e));
    EXPECT_EQ(text(emcyFrame(3, {0x8130, 0x11, {}})), "083#3081110000000000");
}

TEST(Emcy, ClassesAndTextsOfCiA301And402) {
    EXPECT_STREQ(emcyClassName(0x0000), "error reset");
    EXPECT_STREQ(emcyClassName(0x2310), "current");
    EXPECT_STREQ(emcyClassName(0x3210), "voltage");
    EXPECT_STREQ(emcyClassName(0x4310), "temperature");
    EXPECT_STREQ(emcyClassName(0x5530), "device hardware");
    EXPECT_STREQ(emcyClassName(0x6010), "device software");
    EXPECT_STREQ(emcyClassName(0x7305), "additional modules");
    EXPECT_STREQ(emcyClassName(0x8130), "communication");
    EXPECT_STREQ(emcyClassName(0x8611), "monitoring");
    EXPECT_STREQ(emcyCodeText(0x8611), "following error");
    EXPECT_STREQ(emcyCodeText(0x8130), "life guard or heartbeat error");
    EXPECT_STREQ(emcyCodeText(0x8120), "CAN in error passive mode");
    EXPECT_STREQ(emcyCodeText(0x4321), "temperature");
    // 0x1001: bit 0 generic, 1 current, 2 voltage, 3 temperature, 4 communication, 5 profile.
    EXPECT_EQ(errorRegisterFor(0x4310), 0x09);
    EXPECT_EQ(errorRegisterFor(0x8130), 0x11);
    EXPECT_EQ(errorRegisterFor(0x8611), 0x21);
    EXPECT_EQ(errorRegisterFor(0x0000), 0x00);
}

TEST(Sync, OneFramePerPeriodWithoutBurstsAfterADelay) {
    SyncProducer s;
    s.configure(2ms);
    EXPECT_FALSE(s.due(0ms));
    s.start(0ms);
    ASSERT_TRUE(s.due(0ms));
    EXPECT_EQ(text(s.produce(0ms)), "080#");
    EXPECT_FALSE(s.due(1ms));
    EXPECT_TRUE(s.due(2ms));
    s.produce(5ms);  // a late caller
    EXPECT_FALSE(s.due(5ms));
    EXPECT_TRUE(s.due(6ms));
    EXPECT_EQ(s.produced(), 2u);
}

TEST(Sync, CounterRunsFromOneToTheOverflowValue) {
    SyncProducer s;
    s.configure(1ms, 3);
    s.start(0ms);
    EXPECT_EQ(text(s.produce(0ms)), "080#01");
    EXPECT_EQ(text(s.produce(1ms)), "080#02");
    EXPECT_EQ(text(s.produce(2ms)), "080#03");
    EXPECT_EQ(text(s.produce(3ms)), "080#01");
}

TEST(Pdo, MappingEntriesAsTheStandardWritesThem) {
    EXPECT_EQ((PdoEntry{0x6040, 0, 16}.value()), 0x60400010u);
    EXPECT_EQ((PdoEntry{0x607A, 0, 32}.value()), 0x607A0020u);
    EXPECT_EQ(PdoEntry::fromValue(0x60640020), (PdoEntry{0x6064, 0, 32}));
    PdoLayout tpdo;
    ASSERT_TRUE(tpdo.add({0x6041, 0, 16}));
    ASSERT_TRUE(tpdo.add({0x6064, 0, 32}));
    EXPECT_EQ(tpdo.byteLength(), 6);
    EXPECT_EQ(tpdo.offsetOf({0x6064, 0}), 2);
    EXPECT_EQ(tpdo.offsetOf({0x6077, 0}), -1);
    EXPECT_TRUE(tpdo.add({0x6077, 0, 16}));
    EXPECT_FALSE(tpdo.add({0x606C, 0, 32})) << "64 bits at most";
    EXPECT_FALSE(tpdo.add({0x6060, 0, 4})) << "whole bytes only";
}

TEST(Pdo, ValuesAreLittleEndian) {
    std::array<uint8_t, 8> data{};
    packField(data, 0, 2, 0x000F);
    packField(data, 2, 4, static_cast<uint32_t>(-1000));
    EXPECT_EQ(text(can::makeFrame(0x201, {data[0], data[1], data[2], data[3], data[4], data[5]})),
              "201#0F0018FCFFFF");
    EXPECT_EQ(static_cast<int32_t>(unpackField(data, 2, 4)), -1000);
    EXPECT_EQ(unpackField(data, 0, 2), 0x000Fu);
}

// A2.5: with one 6-byte RPDO and TPDO per axis, 3 axes at 1 ms are 617-745 bit times (62-75 %),
// 4 axes 807-975 (81-98 %), 5 axes above 100 %; at 2 ms 4 axes are 40-49 %, 6 axes 59-72 %.
TEST(BusLoad, FiguresOfTheSpec) {
    auto load = [](int axes, std::chrono::nanoseconds cycle) {
        std::vector<uint8_t> pdos(static_cast<size_t>(2 * axes), 6);
        return estimateBusLoad(1'000'000, cycle, pdos, 0, 100ms);
    };
    BusLoad three = load(3, 1ms);
    EXPECT_EQ(three.cycleBitsMin, 617u);
    EXPECT_EQ(three.cycleBitsMax, 745u);
    EXPECT_EQ(three.cycleBitTimes, 1000u);
    EXPECT_TRUE(three.acceptable());
    BusLoad four = load(4, 1ms);
    EXPECT_EQ(four.cycleBitsMin, 807u);
    EXPECT_EQ(four.cycleBitsMax, 975u);
    EXPECT_FALSE(four.acceptable());
    EXPECT_GT(load(5, 1ms).worstCase, 1.0);
    BusLoad fourSlow = load(4, 2ms);
    EXPECT_NEAR(fourSlow.minimum, 0.40, 0.005);
    EXPECT_NEAR(fourSlow.worstCase, 0.49, 0.005);
    EXPECT_TRUE(fourSlow.acceptable());
    BusLoad six = load(6, 2ms);
    EXPECT_NEAR(six.minimum, 0.59, 0.005);
    EXPECT_NEAR(six.worstCase, 0.72, 0.005);
}

// Five 1-byte heartbeats every 100 ms, at most 65 bits each: 3250 bit/s of a 1 Mbit/s bus.
TEST(BusLoad, HeartbeatsAddTheirAverage) {
    std::vector<uint8_t> pdos(8, 6);
    BusLoad load = estimateBusLoad(1'000'000, 2ms, pdos, 5, 100ms);
    EXPECT_NEAR(load.heartbeatLoad, 0.00325, 1e-9);
    EXPECT_NEAR(load.worstCase, 975.0 / 2000.0 + 0.00325, 1e-9);
}

}  // namespace
}  // namespace kerf::drivers::canopen
