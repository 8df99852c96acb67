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
    auto units = static_cast<uint64_t>(scaled);
    if (units != 0 && value < 0) out += '-';
    const uint64_t integral = units / static_cast<uint64_t>(scale);
    uint64_t fraction = units % static_cast<uint64_t>(scale);
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, integral);
    out.append(buffer, result.ptr);
    if (decimals == 0) return;
    out += '.';
    char digits[10];
    for (int i = decimals - 1; i >= 0; --i) {
        digits[i] = static_cast<char>('0' + fraction % 10);
        fraction /= 10;
    }
    out.append(digits, static_cast<size_t>(decimals));
}

std::string formatFixed(double value, int decimals) {
    std::string out;
    appendFixed(out, value, decimals);
    return out;
}

}  // namespace kerf
