#include "core/base/fixed_format.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

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

// What the C library prints, with the one documented difference: no "-0.000".
std::string printed(double value, int decimals) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    if (text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
    return text;
}

TEST(FixedFormat, EveryMagnitudeMatchesTheCLibrary) {
    // Above 1e63 the old code appended 64 bytes of an uninitialised buffer.
    const double values[] = {1e63,
                             -1e63,
                             1.5e64,
                             1e100,
                             -1e200,
                             1e300,
                             DBL_MAX,
                             -DBL_MAX,
                             9e15,
                             -9.1e15,
                             1e-300,
                             -1e-300,
                             DBL_MIN,
                             -DBL_MIN,
                             4.9e-324,
                             2.5e17,
                             -123456789012345678.0};
    for (const double value : values) {
        for (int decimals = 0; decimals <= 9; ++decimals) {
            EXPECT_EQ(formatFixed(value, decimals), printed(value, decimals))
                << value << " with " << decimals << " decimals";
        }
    }
    EXPECT_EQ(formatFixed(DBL_MAX, 9).size(), 309u + 1 + 9);
    EXPECT_EQ(formatFixed(-DBL_MAX, 9).size(), 1 + 309u + 1 + 9);
}

TEST(FixedFormat, AppendsAfterWhatIsThere) {
    std::string text = "X";
    appendFixed(text, 1e300, 3);
    EXPECT_EQ(text, "X" + printed(1e300, 3));
}

TEST(FixedFormat, NonFiniteValuesAreNamed) {
    EXPECT_EQ(formatFixed(std::numeric_limits<double>::infinity(), 3), "inf");
    EXPECT_EQ(formatFixed(-std::numeric_limits<double>::infinity(), 0), "-inf");
    EXPECT_EQ(formatFixed(std::numeric_limits<double>::quiet_NaN(), 3), "nan");
}

}  // namespace
}  // namespace kerf

TEST(FixedFormat, MessagesShowHugeValuesShort) {
    // What a machinist writes keeps its decimals; 10^300 in a cycle parameter is not 301 digits.
    EXPECT_EQ(kerf::formatForMessage(3600.0, 4), "3600.0000");
    EXPECT_EQ(kerf::formatForMessage(-12.5, 2), "-12.50");
    EXPECT_EQ(kerf::formatForMessage(1e300, 4), "1e+300");
    EXPECT_EQ(kerf::formatForMessage(-2.5e12, 4), "-2.5e+12");
    EXPECT_EQ(kerf::formatForMessage(std::numeric_limits<double>::infinity(), 4), "inf");
}

TEST(FixedFormat, UnsafeValuesAreDescribedShortly) {
    EXPECT_EQ(kerf::formatShort(1e200), "1e+200");
    EXPECT_EQ(kerf::formatShort(-std::numeric_limits<double>::infinity()), "-inf");
    EXPECT_EQ(kerf::formatShort(1500000), "1500000");
}
