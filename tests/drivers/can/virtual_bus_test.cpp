#include "drivers/can/virtual_bus.h"

#include <vector>

#include <gtest/gtest.h>

#include "drivers/can/bit_timing.h"

namespace kerf::drivers::can {
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;

struct Recorder final : FrameObserver {
    struct Entry {
        nanoseconds time;
        CanFrame frame;
    };
    std::vector<Entry> frames;
    void onFrame(nanoseconds time, const CanFrame& frame) noexcept override {
        frames.push_back({time, frame});
    }
};

std::vector<uint32_t> receivedIds(VirtualChannel& c) {
    std::vector<uint32_t> ids;
    CanFrame f;
    while (c.receive(f))
        ids.push_back(f.id);
    return ids;
}

TEST(VirtualBus, DeliversToEveryOtherChannelNotBackToTheSender) {
    VirtualBus bus(0);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& b = bus.attach("b");
    VirtualChannel& c = bus.attach("c");
    ASSERT_FALSE(a.send(makeFrame(0x123, {1, 2, 3})));
    bus.advanceTo(0ns);
    CanFrame f;
    EXPECT_FALSE(a.receive(f));
    ASSERT_TRUE(b.receive(f));
    EXPECT_EQ(f, makeFrame(0x123, {1, 2, 3}));
    ASSERT_TRUE(c.receive(f));
    EXPECT_FALSE(c.receive(f));
}

// Frames waiting together go out in identifier order: the lowest identifier wins arbitration.
TEST(VirtualBus, ArbitratesByIdentifier) {
    VirtualBus bus(1'000'000);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& b = bus.attach("b");
    VirtualChannel& c = bus.attach("c");
    VirtualChannel& listener = bus.attach("listener");
    a.send(makeFrame(0x300, {}));
    b.send(makeFrame(0x100, {}));
    c.send(makeFrame(0x200, {}));
    bus.advanceTo(10ms);
    EXPECT_EQ(receivedIds(listener), (std::vector<uint32_t>{0x100, 0x200, 0x300}));
}

// An 11-bit frame beats a 29-bit frame with the same base identifier (SRR/IDE are recessive).
TEST(VirtualBus, StandardFrameWinsOverExtendedWithTheSameBase) {
    VirtualBus bus(500'000);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& b = bus.attach("b");
    VirtualChannel& listener = bus.attach("listener");
    CanFrame extended = makeFrame(0, {});
    extended.extended = true;
    extended.id = 0x100u << 18;
    a.send(extended);
    b.send(makeFrame(0x100, {}));
    bus.advanceTo(10ms);
    CanFrame first;
    ASSERT_TRUE(listener.receive(first));
    EXPECT_FALSE(first.extended);
}

TEST(VirtualBus, FramesTakeTheirBitTimesBackToBack) {
    VirtualBus bus(1'000'000);
    VirtualChannel& a = bus.attach("a");
    bus.attach("b");
    Recorder recorder;
    bus.addObserver(recorder);
    CanFrame sync = makeFrame(0x080, {});
    CanFrame pdo = makeFrame(0x181, {0x37, 0x02, 0x10, 0x27, 0x00, 0x00});
    a.send(sync);
    a.send(pdo);
    EXPECT_EQ(bus.nextDelivery(), nanoseconds(51us));
    bus.advanceTo(100us);  // the PDO (101 bits) ends at 152 us
    ASSERT_EQ(recorder.frames.size(), 1u);
    EXPECT_EQ(recorder.frames[0].time, 51us);
    bus.advanceTo(1ms);
    ASSERT_EQ(recorder.frames.size(), 2u);
    EXPECT_EQ(recorder.frames[1].time, 152us);
    EXPECT_EQ(bus.busyTime(), 152us);
}

// A frame that arrives while the bus is busy waits even if its identifier is lower.
TEST(VirtualBus, NoPreemptionOfAFrameOnTheWire) {
    VirtualBus bus(1'000'000);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& b = bus.attach("b");
    VirtualChannel& listener = bus.attach("listener");
    a.send(makeFrame(0x700, {0}));
    bus.advanceTo(10us);
    b.send(makeFrame(0x080, {}));
    bus.advanceTo(1ms);
    EXPECT_EQ(receivedIds(listener), (std::vector<uint32_t>{0x700, 0x080}));
}

TEST(VirtualBus, DropDelayAndDuplicate) {
    VirtualBus bus(1'000'000);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& listener = bus.attach("listener");
    Recorder recorder;
    bus.addObserver(recorder);
    ASSERT_TRUE(
        bus.addFault({BusFaultKind::Drop, 0x181, kStandardIdMask, 0ns, nanoseconds::max(), 1}));
    ASSERT_TRUE(bus.addFault(
        {BusFaultKind::Delay, 0x182, kStandardIdMask, 0ns, nanoseconds::max(), -1, 300us}));
    ASSERT_TRUE(bus.addFault({BusFaultKind::Duplicate, 0x183, kStandardIdMask}));
    a.send(makeFrame(0x181, {1}));  // dropped once
    a.send(makeFrame(0x181, {2}));  // the count is used up: delivered
    bus.advanceTo(1ms);
    EXPECT_EQ(bus.droppedFrames(), 1u);
    EXPECT_EQ(receivedIds(listener), (std::vector<uint32_t>{0x181}));
    recorder.frames.clear();
    a.send(makeFrame(0x182, {}));
    bus.advanceTo(1100us);
    EXPECT_TRUE(recorder.frames.empty()) << "delayed by 300 us";
    bus.advanceTo(2ms);
    ASSERT_EQ(recorder.frames.size(), 1u);
    EXPECT_EQ(recorder.frames[0].time,
              1ms + 300us + frameDuration(makeFrame(0x182, {}), 1'000'000));
    receivedIds(listener);
    a.send(makeFrame(0x183, {7}));
    bus.advanceTo(3ms);
    EXPECT_EQ(receivedIds(listener), (std::vector<uint32_t>{0x183, 0x183}));
}

TEST(VirtualBus, FaultsApplyOnlyInTheirTimeWindow) {
    VirtualBus bus(0);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& listener = bus.attach("listener");
    bus.addFault({BusFaultKind::Drop, 0x180, 0x780, 5ms, 10ms});  // every TPDO1 in [5, 10) ms
    a.send(makeFrame(0x181, {}));
    bus.advanceTo(5ms);
    a.send(makeFrame(0x182, {}));
    bus.advanceTo(10ms);
    a.send(makeFrame(0x183, {}));
    bus.advanceTo(11ms);
    EXPECT_EQ(receivedIds(listener), (std::vector<uint32_t>{0x181, 0x183}));
}

TEST(VirtualBus, BusOffControllerCannotSendOrReceive) {
    VirtualBus bus(0);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& b = bus.attach("b");
    a.send(makeFrame(0x201, {}));
    bus.setState(a, ControllerState::BusOff);  // its queued frame is gone too
    EXPECT_EQ(a.state(), ControllerState::BusOff);
    EXPECT_EQ(a.send(makeFrame(0x202, {})), std::make_error_code(std::errc::network_down));
    b.send(makeFrame(0x181, {}));
    bus.advanceTo(1ms);
    CanFrame f;
    EXPECT_FALSE(a.receive(f));
    EXPECT_FALSE(b.receive(f));
    bus.setState(a, ControllerState::ErrorActive);
    EXPECT_FALSE(a.send(makeFrame(0x203, {})));
    bus.advanceTo(2ms);
    EXPECT_EQ(receivedIds(b), (std::vector<uint32_t>{0x203}));
}

TEST(VirtualBus, ErrorPassiveIsReportedButFramesFlow) {
    VirtualBus bus(0);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& b = bus.attach("b");
    bus.setState(a, ControllerState::ErrorPassive);
    EXPECT_EQ(a.state(), ControllerState::ErrorPassive);
    a.send(makeFrame(0x181, {}));
    bus.advanceTo(1ms);
    EXPECT_EQ(receivedIds(b), (std::vector<uint32_t>{0x181}));
}

TEST(VirtualBus, FullQueuesFailOrCountOverruns) {
    VirtualBus bus(0);
    VirtualChannel& a = bus.attach("a");
    VirtualChannel& b = bus.attach("b");
    for (int i = 0; i < 64; ++i)
        ASSERT_FALSE(a.send(makeFrame(0x181, {})));
    EXPECT_EQ(a.send(makeFrame(0x181, {})), std::make_error_code(std::errc::no_buffer_space));
    bus.advanceTo(1ms);
    for (int round = 0; round < 4; ++round) {
        for (int i = 0; i < 60; ++i)
            a.send(makeFrame(0x181, {}));
        bus.advanceTo(2ms + round * 1ms);
    }
    // b read nothing: 64 + 240 frames for 256 receive slots.
    EXPECT_EQ(b.receiveOverruns(), 64u + 240u - 256u);
}

}  // namespace
}  // namespace kerf::drivers::can
