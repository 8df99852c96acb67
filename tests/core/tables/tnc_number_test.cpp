#include "core/tables/tnc_number.h"

#include <gtest/gtest.h>

namespace kerf::tables {
namespace {

TEST(TncNumber, ParsesSignsPointsAndCommas) {
    EXPECT_EQ(parseTncNumber("+0,000"), 0.0);
    EXPECT_EQ(parseTncNumber("-4,686"), -4.686);
    EXPECT_EQ(parseTncNumber("+18.892"), 18.892);
    EXPECT_EQ(parseTncNumber("  12  "), 12.0);
    EXPECT_EQ(parseTncNumber("+.5"), 0.5);
    EXPECT_EQ(parseTncNumber("5."), 5.0);
    EXPECT_EQ(parseTncNumber("-0"), 0.0);
}

TEST(TncNumber, RejectsWhatIsNotANumber) {
    EXPECT_FALSE(parseTncNumber(""));
    EXPECT_FALSE(parseTncNumber("   "));
    EXPECT_FALSE(parseTncNumber("+"));
    EXPECT_FALSE(parseTncNumber(","));
    EXPECT_FALSE(parseTncNumber("1,2,3"));
    EXPECT_FALSE(parseTncNumber("%00000000"));
    EXPECT_FALSE(parseTncNumber("1e5"));
    EXPECT_FALSE(parseTncNumber("- 5"));
    EXPECT_FALSE(parseTncNumber("12MM"));
}

TEST(TncNumber, ReportsTheStyleAsWritten) {
    EXPECT_EQ(numberStyleOf("+0,000"), (NumberStyle{true, ',', 3}));
    EXPECT_EQ(numberStyleOf("-1"), (NumberStyle{false, '.', 0}));
    EXPECT_EQ(numberStyleOf("0.5"), (NumberStyle{false, '.', 1}));
    EXPECT_FALSE(numberStyleOf("L"));
}

TEST(TncNumber, FormatsLikeTheControl) {
    EXPECT_EQ(formatTncNumber(-4.686, {true, ',', 3}), "-4,686");
    EXPECT_EQ(formatTncNumber(18.892, {true, ',', 3}), "+18,892");
    EXPECT_EQ(formatTncNumber(0.0, {true, '.', 0}), "+0");
    EXPECT_EQ(formatTncNumber(7.0, {false, '.', 0}), "7");
    EXPECT_EQ(formatTncNumber(0.5, {true, '.', 1}), "+0.5");
    // Rounds half away from zero and never writes "-0".
    EXPECT_EQ(formatTncNumber(-0.0001, {true, ',', 3}), "+0,000");
    EXPECT_EQ(formatTncNumber(2.0005, {false, '.', 3}), "2.001");
}

TEST(TncNumber, MinimalDecimals) {
    EXPECT_EQ(minimalDecimals(3.0, 5), 0);
    EXPECT_EQ(minimalDecimals(1.25, 5), 2);
    EXPECT_EQ(minimalDecimals(0.1 + 0.2, 5), 1);
    EXPECT_EQ(minimalDecimals(1.23456789, 5), 5);
    EXPECT_EQ(minimalDecimals(-4.686, 5), 3);
}

}  // namespace
}  // namespace kerf::tables
