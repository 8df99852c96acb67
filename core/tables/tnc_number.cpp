#include "core/tables/tnc_number.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/base/fixed_format.h"
#include "core/tables/detail/table_line.h"

namespace kerf::tables {

namespace {

using detail::trimSpaces;

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// Splits a number into its parts; false if the text is not a table number.
struct NumberParts {
    char sign = 0;
    std::string_view integral;
    char separator = 0;
    std::string_view fraction;
};

bool splitNumber(std::string_view text, NumberParts& parts) {
    size_t i = 0;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) parts.sign = text[i++];
    size_t start = i;
    while (i < text.size() && isDigit(text[i]))
        ++i;
    parts.integral = text.substr(start, i - start);
    if (i < text.size() && (text[i] == '.' || text[i] == ',')) {
        parts.separator = text[i++];
        start = i;
        while (i < text.size() && isDigit(text[i]))
            ++i;
        parts.fraction = text.substr(start, i - start);
    }
    return i == text.size() && (!parts.integral.empty() || !parts.fraction.empty());
}

}  // namespace

std::optional<double> parseTncNumber(std::string_view text) {
    NumberParts parts;
    if (!splitNumber(trimSpaces(text), parts)) return std::nullopt;
    // from_chars wants "-12.5": no '+', a point, at least one integral digit.
    std::string normalized;
    if (parts.sign == '-') normalized += '-';
    normalized += parts.integral.empty() ? std::string_view("0") : parts.integral;
    if (!parts.fraction.empty()) {
        normalized += '.';
        normalized += parts.fraction;
    }
    double value = 0.0;
    auto result = std::from_chars(normalized.data(), normalized.data() + normalized.size(), value);
    if (result.ec != std::errc() || result.ptr != normalized.data() + normalized.size()) {
        return std::nullopt;
    }
    return value;
}

std::optional<NumberStyle> numberStyleOf(std::string_view text) {
    NumberParts parts;
    if (!splitNumber(trimSpaces(text), parts)) return std::nullopt;
    NumberStyle style;
    style.explicitSign = parts.sign == '+';
    if (parts.separator != 0) style.decimalSeparator = parts.separator;
    style.decimals = static_cast<int>(parts.fraction.size());
    return style;
}

std::string formatTncNumber(double value, const NumberStyle& style) {
    std::string digits = formatFixed(value, std::clamp(style.decimals, 0, 9));
    if (style.decimalSeparator != '.')
        std::replace(digits.begin(), digits.end(), '.', style.decimalSeparator);
    if (style.explicitSign && digits.front() != '-') digits.insert(digits.begin(), '+');
    return digits;
}

int minimalDecimals(double value, int maxDecimals) {
    const double tolerance = 1e-9 * std::max(1.0, std::fabs(value));
    double scale = 1.0;
    for (int decimals = 0; decimals < maxDecimals; ++decimals) {
        if (std::fabs(std::round(value * scale) / scale - value) <= tolerance) return decimals;
        scale *= 10.0;
    }
    return maxDecimals;
}

}  // namespace kerf::tables
