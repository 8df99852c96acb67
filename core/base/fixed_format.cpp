#include "core/base/fixed_format.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>

namespace kerf {

namespace {

constexpr int64_t kPowersOfTen[] = {1,      10,      100,      1000,      10000,
                                    100000, 1000000, 10000000, 100000000, 1000000000};

constexpr size_t kLongestFixed = 1 + 309 + 1 + 9;

}  // namespace

void appendFixed(std::string& out, double value, int decimals) {
    if (decimals < 0) decimals = 0;
    if (decimals > 9) decimals = 9;
    const int64_t scale = kPowersOfTen[decimals];
    const double magnitude = std::fabs(value) * static_cast<double>(scale);
    if (!(magnitude < 9.0e15)) {  // also NaN and infinity
        // The largest double has 309 integral digits: sign, digits, point and 9 decimals fit.
        char buffer[kLongestFixed];
        auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed,
                                    decimals);
        out.append(buffer, result.ptr);
        return;
    }
    // Digits are written backwards into a small buffer: fraction, point, integral part, sign.
    // Round half away from zero without a libm call: below 2^53 the truncation and the
    // remainder are exact.
    auto units = static_cast<uint64_t>(magnitude);
    if (magnitude - static_cast<double>(units) >= 0.5) ++units;
    const bool negative = units != 0 && value < 0;
    uint64_t integral = units / static_cast<uint64_t>(scale);
    uint64_t fraction = units % static_cast<uint64_t>(scale);
    char buffer[32];
    char* end = buffer + sizeof buffer;
    char* p = end;
    for (int i = 0; i < decimals; ++i) {
        *--p = static_cast<char>('0' + fraction % 10);
        fraction /= 10;
    }
    if (decimals > 0) *--p = '.';
    // The integral part is usually small: two digits per step.
    static constexpr char kPairs[] =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
        "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
        "8081828384858687888990919293949596979899";
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
    out.append(p, static_cast<size_t>(end - p));
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
