#pragma once

#include <cstddef>
#include <string>

namespace kerf {

// The most characters writeFixed writes: sign, the 309 integral digits of the largest double,
// point and 9 decimals.
inline constexpr size_t kMaxFixedChars = 1 + 309 + 1 + 9;

// appendFixed's text written at `out`, which has room for kMaxFixedChars; returns its end.
char* writeFixed(char* out, double value, int decimals);

// Appends value with exactly `decimals` fraction digits (0..9), rounded half away from zero, never
// "-0.000". Used by traces and reports, whose text must be stable across runs and platforms.
void appendFixed(std::string& out, double value, int decimals);

std::string formatFixed(double value, int decimals);

// Nine significant digits, exponent when shorter: "1e+200", "-inf", "1500000". For messages
// about values that may be huge or not finite.
std::string formatShort(double value);

// For messages: like formatFixed while the number is of a size a machinist writes; a huge or
// non-finite value as formatShort gives it ("1e+300", "inf") instead of hundreds of digits.
std::string formatForMessage(double value, int decimals);

}  // namespace kerf
