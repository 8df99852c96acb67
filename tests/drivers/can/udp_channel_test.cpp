#include "drivers/can/udp_channel.h"

#include <array>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/can/cannelloni_codec.h"

namespace kerf::drivers::can {
namespace {

// cannelloni v2: {version 2, op 0 DATA, sequence, count (BE u16)}, then per frame {can_id BE u32
// with the EFF (bit 31) and RTR (bit 30) flags of <linux/can.h>, length, data}.
TEST(Cannelloni, EncodesOneFramePerDatagram) {
    std::array<uint8_t, 32> out{};
    size_t n = encodeCannelloni(makeFrame(0x181, {0x37, 0x02, 0x10, 0x27, 0x00, 0x00}), 7, out);
    std::vector<uint8_t> bytes(out.begin(), out.begin() + static_cast<long>(n));
    EXPECT_EQ(bytes, (std::vector<uint8_t>{0x02, 0x00, 0x07, 0x00, 0x01, 0x00, 0x00, 0x01, 0x81,
                                           0x06, 0x37, 0x02, 0x10, 0x27, 0x00, 0x00}));
    CanFrame remote;
    remote.id = 0x18FF1234;
    remote.extended = true;
    remote.remote = true;
    remote.length = 1;
    n = encodeCannelloni(remote, 0, out);
    bytes.assign(out.begin(), out.begin() + static_cast<long>(n));
    EXPECT_EQ(bytes,
              (std::vector<uint8_t>{0x02, 0x00, 0x00, 0x00, 0x01, 0xD8, 0xFF, 0x12, 0x34, 0x01}));
}

TEST(Cannelloni, DecodesDatagramsWithSeveralFrames) {
    std::vector<uint8_t> datagram{0x02, 0x00, 0x2A, 0x00, 0x02,         // two frames
                                  0x00, 0x00, 0x00, 0x80, 0x00,         // SYNC
                                  0x00, 0x00, 0x07, 0x01, 0x01, 0x05};  // heartbeat 05
    std::array<CanFrame, 4> frames{};
    ASSERT_EQ(decodeCannelloni(datagram, frames), 2);
    EXPECT_EQ(frames[0], makeFrame(0x080, {}));
    EXPECT_EQ(frames[1], makeFrame(0x701, {0x05}));
}

TEST(Cannelloni, RejectsOtherVersionsCanFdAndTruncation) {
    std::array<CanFrame, 4> frames{};
    std::vector<uint8_t> v1{0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x80, 0x00};
    EXPECT_EQ(decodeCannelloni(v1, frames), -1);
    std::vector<uint8_t> fd{0x02, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x80, 0x81, 0x00, 0x00};
    EXPECT_EQ(decodeCannelloni(fd, frames), -1);
    std::vector<uint8_t> truncated{0x02, 0x00, 0x00, 0x00, 0x01, 0x00,
                                   0x00, 0x01, 0x81, 0x06, 0x37};
    EXPECT_EQ(decodeCannelloni(truncated, frames), -1);
}

bool receiveWithin(UdpChannel& channel, CanFrame& frame) {
    for (int i = 0; i < 500; ++i) {
        if (channel.receive(frame)) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
}

TEST(UdpChannel, FramesCrossTheLoopbackAndPeersAreLearned) {
    UdpChannel master;
    ASSERT_FALSE(master.open(0));
    ASSERT_NE(master.localPort(), 0);
    EXPECT_EQ(master.peerCount(), 0u);
    UdpChannel drive;
    uint16_t peer[] = {master.localPort()};
    ASSERT_FALSE(drive.open(0, peer));
    CanFrame f;
    EXPECT_FALSE(master.receive(f)) << "non-blocking";
    ASSERT_FALSE(drive.send(makeFrame(0x701, {0x00})));
    ASSERT_TRUE(receiveWithin(master, f));
    EXPECT_EQ(f, makeFrame(0x701, {0x00}));
    EXPECT_EQ(master.peerCount(), 1u) << "the drive's port is learned from its datagram";
    ASSERT_FALSE(master.send(makeFrame(0x000, {0x82, 0x01})));
    ASSERT_TRUE(receiveWithin(drive, f));
    EXPECT_EQ(f, makeFrame(0x000, {0x82, 0x01}));
    EXPECT_EQ(drive.state(), ControllerState::ErrorActive);
    drive.close();
    EXPECT_EQ(drive.state(), ControllerState::Stopped);
    EXPECT_EQ(drive.send(f), std::make_error_code(std::errc::not_connected));
}

}  // namespace
}  // namespace kerf::drivers::can
