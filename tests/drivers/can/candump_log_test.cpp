#include "drivers/can/candump_log.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace kerf::drivers::can {
namespace {

using namespace std::chrono_literals;

std::string line(std::chrono::nanoseconds t, const CanFrame& f,
                 std::string_view interface = "can0") {
    char text[kCandumpLineMax + 1];
    size_t n = formatCandumpLine(text, t, interface, f);
    return {text, n};
}

// The format candump -l writes and canplayer reads: "(%010lu.%06lu) %s %03X#%02X...".
TEST(CandumpLog, FormatsLikeCandump) {
    EXPECT_EQ(line(1002ms, makeFrame(0x601, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0})),
              "(0000000001.002000) can0 601#4000100000000000");
    EXPECT_EQ(line(0ns, makeFrame(0x080, {})), "(0000000000.000000) can0 080#");
    EXPECT_EQ(line(123456789us, makeFrame(0x7E5, {0xAB})), "(0000000123.456789) can0 7E5#AB");
    CanFrame extended = makeFrame(0, {0xDE, 0xAD});
    extended.id = 0x1ABCDEF0;
    extended.extended = true;
    EXPECT_EQ(line(5s, extended, "vcan0"), "(0000000005.000000) vcan0 1ABCDEF0#DEAD");
    CanFrame remote = makeFrame(0x701, {});
    remote.remote = true;
    EXPECT_EQ(line(0ns, remote), "(0000000000.000000) can0 701#R");
}

TEST(CandumpLog, ParsesWhatItWrites) {
    CandumpRecord r;
    ASSERT_TRUE(parseCandumpLine("(0000000001.002000) can0 581#4B00100092010000\n", r));
    EXPECT_EQ(r.time, 1002000us);
    EXPECT_EQ(r.interface, "can0");
    EXPECT_EQ(r.frame, makeFrame(0x581, {0x4B, 0x00, 0x10, 0x00, 0x92, 0x01, 0x00, 0x00}));
    ASSERT_TRUE(parseCandumpLine("(1436509052.249713) vcan0 1ABCDEF0#R", r));
    EXPECT_TRUE(r.frame.extended);
    EXPECT_TRUE(r.frame.remote);
    EXPECT_EQ(r.frame.id, 0x1ABCDEF0u);
    ASSERT_TRUE(parseCandumpLine("(0000000000.000100) can0 080# R", r));  // candump -x direction
    EXPECT_EQ(r.frame, makeFrame(0x080, {}));
}

TEST(CandumpLog, RejectsMalformedLines) {
    CandumpRecord r;
    EXPECT_FALSE(parseCandumpLine("", r));
    EXPECT_FALSE(parseCandumpLine("0000000001.002000 can0 601#40", r));
    EXPECT_FALSE(parseCandumpLine("(1.2) can0 601#40", r));  // six microsecond digits
    EXPECT_FALSE(parseCandumpLine("(0000000001.002000) can0 60#40", r));
    EXPECT_FALSE(parseCandumpLine("(0000000001.002000) can0 601#4", r));
    EXPECT_FALSE(parseCandumpLine("(0000000001.002000) can0 601#404142434445464748", r));
    EXPECT_FALSE(parseCandumpLine("(0000000001.002000) can0 801#40", r));  // beyond 11 bits
}

TEST(CandumpLog, WriterAppendsOneLinePerFrame) {
    std::filesystem::path path =
        std::filesystem::path(testing::TempDir()) / "kerf_candump_test.log";
    CandumpWriter writer;
    ASSERT_FALSE(writer.open(path));
    writer.onFrame(2ms, makeFrame(0x000, {0x82, 0x01}));
    writer.onFrame(12ms, makeFrame(0x701, {0x00}));
    ASSERT_FALSE(writer.close());
    std::ifstream in(path);
    std::string a;
    std::string b;
    std::getline(in, a);
    std::getline(in, b);
    EXPECT_EQ(a, "(0000000000.002000) can0 000#8201");
    EXPECT_EQ(b, "(0000000000.012000) can0 701#00");
    EXPECT_FALSE(writer.open("/nonexistent-dir/trace.log") == std::error_code());
}

}  // namespace
}  // namespace kerf::drivers::can
