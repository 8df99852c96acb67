#include "core/base/fixed_format.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>

namespace kerf {

namespace {

constexpr uint64_t kPowersOfTen[] = {1,      10,      100,      1000,      10000,
                                     100000, 1000000, 10000000, 100000000, 1000000000};
constexpr double kScales[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

// Two digits per step: the pair of n is at 2n.
constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

int digitCount(uint64_t value) {
    // Coordinates and feeds have one to five integral digits: compare before dividing.
    if (value < 10) return 1;
    if (value < 100) return 2;
    if (value < 1000) return 3;
    if (value < 10000) return 4;
    int count = 5;
    for (value /= 100000; value != 0; value /= 10)
        ++count;
    return count;
}

}  // namespace

char* writeFixed(char* out, double value, int decimals) {
    if (decimals < 0) decimals = 0;
    if (decimals > 9) decimals = 9;
    const uint64_t scale = kPowersOfTen[decimals];
    const double magnitude = std::fabs(value) * kScales[decimals];
    if (!(magnitude < 9.0e15)) {  // also NaN and infinity
        return std::to_chars(out, out + kMaxFixedChars, value, std::chars_format::fixed, decimals)
            .ptr;
    }
    // Round half away from zero without a libm call: below 2^53 the truncation and the
    // remainder are exact (signed conversions: one instruction each, unsigned ones branch).
    const auto truncated = static_cast<int64_t>(magnitude);
    auto units = static_cast<uint64_t>(truncated);
    if (magnitude - static_cast<double>(truncated) >= 0.5) ++units;
    const bool negative = units != 0 && value < 0;
    uint64_t integral = units / scale;
    uint64_t fraction = units % scale;
    // The length is known first, so the digits are written backwards in place.
    char* const end =
        out + (negative ? 1 : 0) + digitCount(integral) + (decimals > 0 ? 1 + decimals : 0);
    char* p = end;
    int left = decimals;
    for (; left >= 2; left -= 2) {
        const auto pair = static_cast<size_t>(fraction % 100) * 2;
        fraction /= 100;
        *--p = kPairs[pair + 1];
        *--p = kPairs[pair];
    }
    if (left == 1) *--p = static_cast<char>('0' + fraction);
    if (decimals > 0) *--p = '.';
    while (integral >= 100) {
        const auto pair = static_cast<size_t>(integral % 100) * 2;
        integral /= 100;
        *--p = kPairs[pair + 1];
        *--p = kPairs[pair];
    }
    if (integral >= 10) {
        const auto pair = static_cast<size_t>(integral) * 2;
        *--p = kPairs[pair + 1];
        *--p = kPairs[pair];
    } else {
        *--p = static_cast<char>('0' + integral);
    }
    if (negative) *--p = '-';
    return end;
}

void appendFixed(std::string& out, double value, int decimals) {
    char buffer[kMaxFixedChars];
    out.append(buffer, writeFixed(buffer, value, decimals));
}

std::string formatFixed(double value, int decimals) {
    std::string out;
    appendFixed(out, value, decimals);
    return out;
}

std::string formatShort(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

std::string formatForMessage(double value, int decimals) {
    if (std::isfinite(value) && std::fabs(value) < 1e9) return formatFixed(value, decimals);
    return formatShort(value);
}

}  // namespace kerf
