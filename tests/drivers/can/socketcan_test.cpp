#include <cstring>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <linux/can/error.h>
#include <linux/can/netlink.h>
#include <linux/if_link.h>
#include <linux/netlink.h>
#include <linux/rtnetlink.h>

#include "drivers/can/can_error.h"
#include "drivers/can/can_link_info.h"
#include "drivers/can/detail/socketcan_codec.h"
#include "drivers/can/socketcan_channel.h"

namespace kerf::drivers::can {
namespace {

// The socket tests need kernel CAN and a vcan0 interface (modprobe vcan; ip link add dev vcan0
// type vcan; ip link set up vcan0). Without them they skip and say why, never pass silently.
#define KERF_REQUIRE_VCAN0()                                                                   \
    do {                                                                                       \
        if (std::error_code e = probeSocketCan()) {                                            \
            GTEST_SKIP() << "PF_CAN unavailable in this kernel: " << e.message() << " (errno " \
                         << e.value() << ")";                                                  \
        }                                                                                      \
        SocketCanChannel probe;                                                                \
        if (std::error_code e = probe.open("vcan0")) {                                         \
            GTEST_SKIP() << "no vcan0 interface: " << e.message();                             \
        }                                                                                      \
    } while (false)

// --- the socket-free part, tested everywhere --------------------------------------------------

TEST(SocketCanCodec, FramesToAndFromTheKernelLayout) {
    CanFrame f = makeFrame(0x601, {0x40, 0x00, 0x10, 0x00});
    struct can_frame k = detail::toKernelFrame(f);
    EXPECT_EQ(k.can_id, 0x601u);
    EXPECT_EQ(k.can_dlc, 4);
    EXPECT_EQ(k.data[0], 0x40);
    CanFrame back;
    ASSERT_TRUE(detail::fromKernelFrame(k, back));
    EXPECT_EQ(back, f);

    CanFrame extended = makeFrame(0, {1});
    extended.extended = true;
    extended.id = 0x18FF1234;
    k = detail::toKernelFrame(extended);
    EXPECT_EQ(k.can_id, 0x18FF1234u | CAN_EFF_FLAG);
    ASSERT_TRUE(detail::fromKernelFrame(k, back));
    EXPECT_EQ(back, extended);

    CanFrame remote = makeFrame(0x701, {});
    remote.remote = true;
    remote.length = 1;
    k = detail::toKernelFrame(remote);
    EXPECT_EQ(k.can_id, 0x701u | CAN_RTR_FLAG);
    ASSERT_TRUE(detail::fromKernelFrame(k, back));
    EXPECT_TRUE(back.remote);
    EXPECT_EQ(back.length, 1);
}

TEST(SocketCanCodec, ErrorFramesAreNoData) {
    struct can_frame k;
    std::memset(&k, 0, sizeof k);
    k.can_id = CAN_ERR_FLAG | CAN_ERR_BUSOFF;
    k.can_dlc = CAN_ERR_DLC;
    CanFrame f;
    EXPECT_FALSE(detail::fromKernelFrame(k, f));
}

TEST(SocketCanCodec, FiltersMatchStandardDataFramesOnly) {
    struct can_filter k = detail::toKernelFilter({0x180, 0x780});
    EXPECT_EQ(k.can_id, 0x180u);
    EXPECT_EQ(k.can_mask, 0x780u | CAN_EFF_FLAG | CAN_RTR_FLAG);
    k = detail::toKernelFilter({0x18FF0000, 0x1FFF0000, true});
    EXPECT_EQ(k.can_id, 0x18FF0000u | CAN_EFF_FLAG);
    EXPECT_EQ(k.can_mask, 0x1FFF0000u | CAN_EFF_FLAG | CAN_RTR_FLAG);
}

struct can_frame errorFrame(canid_t classes, uint8_t controller) {
    struct can_frame k;
    std::memset(&k, 0, sizeof k);
    k.can_id = CAN_ERR_FLAG | classes;
    k.can_dlc = CAN_ERR_DLC;
    k.data[1] = controller;
    return k;
}

TEST(SocketCanCodec, ErrorFramesChangeTheControllerState) {
    using S = ControllerState;
    auto decode = [](struct can_frame k, S current = S::ErrorActive) {
        return detail::decodeErrorFrame(k, current);
    };
    EXPECT_EQ(decode(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_WARNING)).state, S::ErrorWarning);
    EXPECT_EQ(decode(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_PASSIVE)).state, S::ErrorPassive);
    EXPECT_EQ(decode(errorFrame(CAN_ERR_BUSOFF, 0)).state, S::BusOff);
    EXPECT_EQ(decode(errorFrame(CAN_ERR_RESTARTED, 0), S::BusOff).state, S::ErrorActive);
    EXPECT_EQ(decode(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE), S::ErrorPassive).state,
              S::ErrorActive);
    detail::ErrorFrameInfo overflow = decode(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW));
    EXPECT_TRUE(overflow.overflow);
    EXPECT_FALSE(overflow.stateChanged);
    EXPECT_EQ(overflow.state, S::ErrorActive);
}

// An RTM_NEWLINK reply of a CAN interface: IFLA_LINKINFO { KIND "can", DATA { BITTIMING, STATE } }.
std::vector<uint8_t> canLinkMessage(uint32_t bitrate, uint32_t state, const char* kind = "can") {
    std::vector<uint8_t> m(NLMSG_HDRLEN + NLMSG_ALIGN(sizeof(struct ifinfomsg)));
    auto attribute = [](std::vector<uint8_t>& out, uint16_t type, const void* data, size_t size) {
        size_t at = out.size();
        struct rtattr header;
        header.rta_len = static_cast<unsigned short>(RTA_LENGTH(size));
        header.rta_type = type;
        out.resize(at + RTA_ALIGN(RTA_LENGTH(size)));
        std::memcpy(out.data() + at, &header, sizeof header);
        if (size) std::memcpy(out.data() + at + RTA_LENGTH(0), data, size);
    };
    std::vector<uint8_t> data;
    struct can_bittiming timing {};
    timing.bitrate = bitrate;
    attribute(data, IFLA_CAN_BITTIMING, &timing, sizeof timing);
    attribute(data, IFLA_CAN_STATE, &state, sizeof state);
    std::vector<uint8_t> info;
    attribute(info, IFLA_INFO_KIND, kind, std::strlen(kind) + 1);
    attribute(info, IFLA_INFO_DATA, data.data(), data.size());
    attribute(m, IFLA_LINKINFO, info.data(), info.size());
    struct nlmsghdr header {};
    header.nlmsg_len = static_cast<uint32_t>(m.size());
    header.nlmsg_type = RTM_NEWLINK;
    std::memcpy(m.data(), &header, sizeof header);
    return m;
}

TEST(CanLinkInfo, ParsesBitRateAndStateOfACanLink) {
    CanLinkInfo info;
    std::vector<uint8_t> m = canLinkMessage(500000, CAN_STATE_ERROR_PASSIVE);
    ASSERT_FALSE(parseCanLinkMessage(m, info));
    EXPECT_EQ(info.bitrate, 500000u);
    EXPECT_EQ(info.state, ControllerState::ErrorPassive);
    ASSERT_FALSE(parseCanLinkMessage(canLinkMessage(1000000, CAN_STATE_BUS_OFF), info));
    EXPECT_EQ(info.state, ControllerState::BusOff);
    EXPECT_EQ(parseCanLinkMessage(canLinkMessage(0, 0, "vcan"), info),
              std::error_code(CanErrc::NotCanInterface));
    m.resize(m.size() - 3);  // truncated
    EXPECT_EQ(parseCanLinkMessage(m, info), std::error_code(CanErrc::MalformedReply));
}

// Netlink exists without kernel CAN: the loopback interface is found and is no CAN interface.
TEST(CanLinkInfo, ReadsTheKernelsAnswer) {
    CanLinkInfo info;
    EXPECT_EQ(readCanLinkInfo("lo", info), std::error_code(CanErrc::NotCanInterface));
    EXPECT_EQ(readCanLinkInfo("nosuchcan9", info), std::make_error_code(std::errc::no_such_device));
}

TEST(SocketCan, ClosedChannelRefusesToSend) {
    SocketCanChannel channel;
    EXPECT_EQ(channel.send(makeFrame(0x080, {})), std::make_error_code(std::errc::not_connected));
    CanFrame f;
    EXPECT_FALSE(channel.receive(f));
    EXPECT_EQ(channel.state(), ControllerState::Stopped);
}

TEST(SocketCan, OpenFailsWithTheKernelsReasonWithoutPfCan) {
    std::error_code probe = probeSocketCan();
    if (!probe) GTEST_SKIP() << "this kernel has PF_CAN; the vcan0 tests below cover it";
    SocketCanChannel channel;
    EXPECT_EQ(channel.open("can0"), probe);
    EXPECT_EQ(probe, std::make_error_code(std::errc::address_family_not_supported));
}

// --- with kernel CAN and vcan0 ------------------------------------------------------------------

TEST(SocketCan, FramesGoFromOneSocketToAnother) {
    KERF_REQUIRE_VCAN0();
    SocketCanChannel a;
    SocketCanChannel b;
    ASSERT_FALSE(a.open("vcan0"));
    ASSERT_FALSE(b.open("vcan0"));
    CanFrame f;
    EXPECT_FALSE(b.receive(f)) << "non-blocking: nothing waiting";
    ASSERT_FALSE(a.send(makeFrame(0x601, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0})));
    bool got = false;
    for (int i = 0; i < 100 && !got; ++i) {
        got = b.receive(f);
        if (!got) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_TRUE(got);
    EXPECT_EQ(f, makeFrame(0x601, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
    EXPECT_FALSE(a.receive(f)) << "own frames are not received";
}

TEST(SocketCan, FiltersPassOnlyMatchingIdentifiers) {
    KERF_REQUIRE_VCAN0();
    SocketCanChannel sender;
    SocketCanChannel tpdoOnly;
    ASSERT_FALSE(sender.open("vcan0"));
    CanFilter filter{0x180, 0x780};
    ASSERT_FALSE(tpdoOnly.open("vcan0", {&filter, 1}));
    sender.send(makeFrame(0x601, {}));
    sender.send(makeFrame(0x181, {1}));
    CanFrame f;
    bool got = false;
    for (int i = 0; i < 100 && !got; ++i) {
        got = tpdoOnly.receive(f);
        if (!got) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_TRUE(got);
    EXPECT_EQ(f.id, 0x181u);
}

TEST(SocketCan, VcanHasNoBitTiming) {
    KERF_REQUIRE_VCAN0();
    CanLinkInfo info;
    EXPECT_EQ(readCanLinkInfo("vcan0", info), std::error_code(CanErrc::NotCanInterface));
    SocketCanChannel channel;
    ASSERT_FALSE(channel.open("vcan0"));
    EXPECT_EQ(channel.state(), ControllerState::ErrorActive);
}

}  // namespace
}  // namespace kerf::drivers::can
