#include "core/base/fixed_format.h"

#include <gtest/gtest.h>

namespace kerf {
namespace {

TEST(FixedFormat, PadsAndRounds) {
    EXPECT_EQ(formatFixed(1.5, 4), "1.5000");
    EXPECT_EQ(formatFixed(-0.98565, 4), "-0.9857");  // half away from zero
    EXPECT_EQ(formatFixed(0.00005, 4), "0.0001");
    EXPECT_EQ(formatFixed(12345.0, 0), "12345");
}

TEST(FixedFormat, NeverPrintsNegativeZero) {
    EXPECT_EQ(formatFixed(-0.0, 4), "0.0000");
    EXPECT_EQ(formatFixed(-0.00004, 4), "0.0000");
    EXPECT_EQ(formatFixed(-1e-12, 3), "0.000");
}

TEST(FixedFormat, HugeValuesFallBack) {
    EXPECT_EQ(formatFixed(1e20, 1), "100000000000000000000.0");
}

}  // namespace
}  // namespace kerf
