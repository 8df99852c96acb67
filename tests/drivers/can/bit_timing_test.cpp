#include "drivers/can/bit_timing.h"

#include <random>

#include <gtest/gtest.h>

namespace kerf::drivers::can {
namespace {

// Figures of the spec (A2.5): 47 + 8n bits including intermission, plus up to floor((33+8n)/4)
// stuff bits: SYNC 47-55, a 6-byte PDO 95-115, an 8-byte PDO 111-135.
TEST(BitTiming, BoundsAreThoseOfTheSpec) {
    EXPECT_EQ(unstuffedBitCount(0), 47u);
    EXPECT_EQ(worstCaseBitCount(0), 55u);
    EXPECT_EQ(unstuffedBitCount(6), 95u);
    EXPECT_EQ(worstCaseBitCount(6), 115u);
    EXPECT_EQ(unstuffedBitCount(8), 111u);
    EXPECT_EQ(worstCaseBitCount(8), 135u);
    // 29-bit identifiers: 20 more bits (SRR, IDE, 18-bit extension, r1).
    EXPECT_EQ(unstuffedBitCount(8, true), 131u);
}

// Exact counts cross-checked with an independent script (bit stream, CRC-15 0x4599, stuffing):
// the SYNC frame carries 4 stuff bits, an NMT frame 6, eight 0x55 bytes only 1.
TEST(BitTiming, ExactCountsOfKnownFrames) {
    EXPECT_EQ(frameBitCount(makeFrame(0x080, {})), 51u);
    EXPECT_EQ(frameBitCount(makeFrame(0x000, {0x01, 0x01})), 69u);
    EXPECT_EQ(frameBitCount(makeFrame(0x701, {0x00})), 59u);
    EXPECT_EQ(frameBitCount(makeFrame(0x000, {0, 0, 0, 0, 0, 0, 0, 0})), 127u);
    EXPECT_EQ(frameBitCount(makeFrame(0x555, {0x55, 0x55, 0x55, 0x55, 0x55, 0x55, 0x55, 0x55})),
              112u);
    EXPECT_EQ(frameBitCount(makeFrame(0x181, {0x37, 0x02, 0x10, 0x27, 0x00, 0x00})), 101u);
}

TEST(BitTiming, EveryFrameLiesWithinItsBounds) {
    std::mt19937 random(42);
    for (int i = 0; i < 2000; ++i) {
        CanFrame f;
        f.extended = i % 3 == 0;
        f.id = static_cast<uint32_t>(random()) & (f.extended ? kExtendedIdMask : kStandardIdMask);
        f.length = static_cast<uint8_t>(random() % 9);
        for (auto& b : f.data)
            b = static_cast<uint8_t>(random());
        uint32_t bits = frameBitCount(f);
        EXPECT_GE(bits, unstuffedBitCount(f.length, f.extended));
        EXPECT_LE(bits, worstCaseBitCount(f.length, f.extended));
    }
}

TEST(BitTiming, DurationAtTheBitRate) {
    // 51 bits at 1 Mbit/s are 51 us; at 125 kbit/s 408 us; no timing at bit rate 0.
    EXPECT_EQ(frameDuration(makeFrame(0x080, {}), 1'000'000), std::chrono::microseconds(51));
    EXPECT_EQ(frameDuration(makeFrame(0x080, {}), 125'000), std::chrono::microseconds(408));
    EXPECT_EQ(frameDuration(makeFrame(0x080, {}), 0), std::chrono::nanoseconds(0));
}

TEST(BitTiming, RemoteFramesCarryNoData) {
    CanFrame f = makeFrame(0x701, {});
    f.remote = true;
    f.length = 1;
    // The data length code says one byte, but a remote frame has no data field.
    EXPECT_GE(frameBitCount(f), unstuffedBitCount(0));
    EXPECT_LE(frameBitCount(f), worstCaseBitCount(0));
}

}  // namespace
}  // namespace kerf::drivers::can
