#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

namespace kerf {

// Converts a value computed by a program to an integer type, clamping it to the type's range
// (NaN becomes 0): a cast of an out-of-range double is undefined behaviour in C++.
template <typename Int>
Int saturatingCast(double value) {
    if (std::isnan(value)) return 0;
    constexpr auto lo = static_cast<double>(std::numeric_limits<Int>::lowest());
    constexpr auto hi = static_cast<double>(std::numeric_limits<Int>::max());
    if (value <= lo) return std::numeric_limits<Int>::lowest();
    if (value >= hi) return std::numeric_limits<Int>::max();
    return static_cast<Int>(value);
}

inline int saturatingInt(double value) {
    return saturatingCast<int>(value);
}

}  // namespace kerf
