#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace kerf::tables {

// How the TNC wrote one number: "+12,500" has an explicit sign, a decimal comma and 3 decimals.
struct NumberStyle {
    bool explicitSign = false;
    char decimalSeparator = '.';
    int decimals = 0;

    friend bool operator==(const NumberStyle&, const NumberStyle&) = default;
};

// Reads a table number: optional sign, digits, optional '.' or ',' and digits ("+0,000", "-4.686",
// "12", "+.5"). Surrounding spaces are ignored; anything else (exponents, "%0101", "1,2,3") is not
// a number.
std::optional<double> parseTncNumber(std::string_view text);

// The style in which `text` is written, or nothing if it is not a number.
std::optional<NumberStyle> numberStyleOf(std::string_view text);

// Writes `value` in `style` ("+" only for non-negative values with explicitSign; never "-0").
std::string formatTncNumber(double value, const NumberStyle& style);

// The fewest decimals, at most `maxDecimals`, that show `value` without losing more than rounding
// noise (1.25 -> 2, 3.0 -> 0).
int minimalDecimals(double value, int maxDecimals);

}  // namespace kerf::tables
