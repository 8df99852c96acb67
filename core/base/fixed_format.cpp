#include "core/base/fixed_format.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace kerf {

namespace {

constexpr int64_t kPowersOfTen[] = {1,      10,      100,      1000,      10000,
                                    100000, 1000000, 10000000, 100000000, 1000000000};

}  // namespace

void appendFixed(std::string& out, double value, int decimals) {
    if (decimals < 0) decimals = 0;
    if (decimals > 9) decimals = 9;
    const int64_t scale = kPowersOfTen[decimals];
    const double scaled = std::round(std::fabs(value) * static_cast<double>(scale));
    if (!std::isfinite(value) || scaled > 9.0e17) {
        char buffer[64];
        auto result = std::to_chars(buffer, buffer + sizeof buffer, value,
                                    std::chars_format::fixed, decimals);
        out.append(buffer, result.ptr);
        return;
    }
    // Digits are written backwards into a small buffer: fraction, point, integral part, sign.
    auto units = static_cast<uint64_t>(scaled);
    const bool negative = units != 0 && value < 0;
    char buffer[32];
    char* end = buffer + sizeof buffer;
    char* p = end;
    for (int i = 0; i < decimals; ++i) {
        *--p = static_cast<char>('0' + units % 10);
        units /= 10;
    }
    if (decimals > 0) *--p = '.';
    do {
        *--p = static_cast<char>('0' + units % 10);
        units /= 10;
    } while (units != 0);
    if (negative) *--p = '-';
    out.append(p, static_cast<size_t>(end - p));
}

std::string formatFixed(double value, int decimals) {
    std::string out;
    appendFixed(out, value, decimals);
    return out;
}

}  // namespace kerf
