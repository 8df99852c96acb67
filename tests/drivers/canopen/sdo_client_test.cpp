#include "drivers/canopen/sdo_client.h"

#include <gtest/gtest.h>

#include "drivers/canopen/sdo_abort.h"
#include "tests/drivers/canopen/frames.h"

namespace kerf::drivers::canopen {
namespace {

using namespace std::chrono_literals;
using test::drain;
using test::frame;
using Frames = std::vector<std::string>;

class SdoClientTest : public testing::Test {
protected:
    SdoClientTest() { client.configure(2, 100ms); }
    void respond(const std::string& f, std::chrono::nanoseconds now = 1ms) {
        client.onFrame(frame(f), now, out);
    }
    SdoClient client;
    FrameOutbox out;
};

TEST_F(SdoClientTest, ExpeditedDownload) {
    const uint8_t value[] = {0x64, 0x00};  // 0x1017 = 100 ms, UNSIGNED16
    ASSERT_TRUE(client.download({0x1017, 0}, value, 0ms, out));
    EXPECT_EQ(drain(out), Frames{"602#2B17100064000000"});
    EXPECT_EQ(client.status(), SdoStatus::Busy);
    respond("582#6017100000000000");
    EXPECT_EQ(client.status(), SdoStatus::Done);
    EXPECT_TRUE(drain(out).empty());
}

TEST_F(SdoClientTest, ExpeditedUploadOfEachSize) {
    ASSERT_TRUE(client.upload({0x1000, 0}, 0ms, out));
    EXPECT_EQ(drain(out), Frames{"602#4000100000000000"});
    respond("582#4300100092010200");
    ASSERT_EQ(client.status(), SdoStatus::Done);
    EXPECT_EQ(client.value(), 0x00020192u);
    EXPECT_EQ(client.data().size(), 4u);
    client.acknowledge();
    ASSERT_TRUE(client.upload({0x6061, 0}, 0ms, out));
    drain(out);
    respond("582#4F61600008000000");  // 0x4F: one byte
    EXPECT_EQ(client.data().size(), 1u);
    EXPECT_EQ(client.value(), 8u);
    client.acknowledge();
    ASSERT_TRUE(client.upload({0x6041, 0}, 0ms, out));
    drain(out);
    respond("582#4B41600037020000");  // 0x4B: two bytes
    EXPECT_EQ(client.value(), 0x0237u);
}

// A 26-byte visible string in four segments ("Kerf si", "mulated", " servo ", "drive"): the
// toggle bit alternates 0, 1, 0, 1 and the last segment says 2 unused bytes and c = 1 (0x15).
TEST_F(SdoClientTest, SegmentedUpload) {
    ASSERT_TRUE(client.upload({0x1008, 0}, 0ms, out));
    drain(out);
    respond("582#410810001A000000");
    EXPECT_EQ(drain(out), Frames{"602#6000000000000000"});
    respond("582#004B657266207369");
    EXPECT_EQ(drain(out), Frames{"602#7000000000000000"});
    respond("582#106D756C61746564");
    EXPECT_EQ(drain(out), Frames{"602#6000000000000000"});
    respond("582#0020736572766F20");
    EXPECT_EQ(drain(out), Frames{"602#7000000000000000"});
    respond("582#1564726976650000");
    ASSERT_EQ(client.status(), SdoStatus::Done);
    EXPECT_TRUE(drain(out).empty());
    std::string text(client.data().begin(), client.data().end());
    EXPECT_EQ(text, "Kerf simulated servo drive");
}

// Ten bytes: initiate with the size (0x21), then "0123456" (t = 0, n = 0, c = 0) and "789"
// (t = 1, n = 4, c = 1: 0x19), each confirmed with the toggle echoed (0x20, 0x30).
TEST_F(SdoClientTest, SegmentedDownload) {
    const std::string data = "0123456789";
    ASSERT_TRUE(client.download(
        {0x2001, 0}, {reinterpret_cast<const uint8_t*>(data.data()), data.size()}, 0ms, out));
    EXPECT_EQ(drain(out), Frames{"602#210120000A000000"});
    respond("582#6001200000000000");
    EXPECT_EQ(drain(out), Frames{"602#0030313233343536"});
    respond("582#2000000000000000");
    EXPECT_EQ(drain(out), Frames{"602#1937383900000000"});
    EXPECT_EQ(client.status(), SdoStatus::Busy);
    respond("582#3000000000000000");
    EXPECT_EQ(client.status(), SdoStatus::Done);
}

TEST_F(SdoClientTest, AbortFromTheServerIsAnErrorCode) {
    const uint8_t value[] = {0x01, 0x00, 0x00, 0x00};
    ASSERT_TRUE(client.download({0x1000, 0}, value, 0ms, out));
    drain(out);
    respond("582#8000100002000106");  // 0x06010002: write to a read-only object
    ASSERT_EQ(client.status(), SdoStatus::Failed);
    EXPECT_EQ(client.error(), SdoAbort::WriteOfReadOnly);
    EXPECT_EQ(client.error().category().name(), std::string("canopen.sdo"));
    EXPECT_EQ(client.error().message(),
              "SDO abort 0x06010002: attempt to write a read only object");
    EXPECT_TRUE(drain(out).empty()) << "the client does not answer an abort";
    client.acknowledge();
    EXPECT_EQ(client.status(), SdoStatus::Idle);
}

TEST_F(SdoClientTest, AnAbortForAnotherObjectIsIgnored) {
    ASSERT_TRUE(client.upload({0x6061, 0}, 0ms, out));
    respond("582#8041600000000206");
    EXPECT_EQ(client.status(), SdoStatus::Busy);
}

TEST_F(SdoClientTest, TimeoutAbortsTheTransfer) {
    ASSERT_TRUE(client.upload({0x1018, 1}, 10ms, out));
    drain(out);
    client.advance(109ms, out);
    EXPECT_EQ(client.status(), SdoStatus::Busy);
    client.advance(110ms, out);
    ASSERT_EQ(client.status(), SdoStatus::Failed);
    EXPECT_EQ(client.error(), SdoAbort::Timeout);
    EXPECT_EQ(drain(out), Frames{"602#8018100100000405"});  // abort 0x05040000 to the server
}

TEST_F(SdoClientTest, ToggleErrorAbortsTheTransfer) {
    ASSERT_TRUE(client.upload({0x1008, 0}, 0ms, out));
    drain(out);
    respond("582#410810001A000000");
    drain(out);
    respond("582#104B657266207369");  // toggle 1, expected 0
    ASSERT_EQ(client.status(), SdoStatus::Failed);
    EXPECT_EQ(client.error(), SdoAbort::ToggleBit);
    EXPECT_EQ(drain(out), Frames{"602#8008100000000305"});
}

TEST_F(SdoClientTest, OneTransferAtATime) {
    ASSERT_TRUE(client.upload({0x1000, 0}, 0ms, out));
    EXPECT_FALSE(client.upload({0x1001, 0}, 0ms, out));
    const uint8_t value[] = {1};
    EXPECT_FALSE(client.download({0x6060, 0}, value, 0ms, out));
}

TEST(SdoAbortCodes, CategoryNamesTheStandardText) {
    std::error_code e = SdoAbort::DeviceState;
    EXPECT_EQ(e.message(),
              "SDO abort 0x08000022: data cannot be transferred or stored to the application "
              "because of the present device state");
    EXPECT_EQ(sdoError(0x06040041), SdoAbort::NotMappable);
    EXPECT_EQ(abortCodeOf(SdoAbort::NoSubIndex), 0x06090011u);
    EXPECT_EQ(abortCodeOf(std::make_error_code(std::errc::timed_out)), 0x08000000u);
    EXPECT_EQ(sdoError(0x0BADC0DE).message(), "SDO abort 0x0BADC0DE: unknown abort code");
}

}  // namespace
}  // namespace kerf::drivers::canopen
