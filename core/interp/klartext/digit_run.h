#pragma once

// Runs of ASCII digits read eight bytes at a time (the literal numbers and block numbers of CAM
// programs): a word of eight characters, the first in its lowest byte.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace kerf::klartext {

// The high bit of every byte of `chunk` that is not an ASCII digit (bytes of 0x80 and above
// included). No carry crosses into a lower byte, so the lowest set bit is exact.
inline uint64_t notDigits(uint64_t chunk) {
    constexpr uint64_t kHigh = 0x8080808080808080ull;
    const uint64_t above = chunk + 0x4646464646464646ull;               // > '9'
    const uint64_t below = ~((chunk | kHigh) - 0x3030303030303030ull);  // < '0'
    return (above | below | chunk) & kHigh;
}

// The value of the `count` (1 to 8) ASCII digits in the low bytes of `chunk`, the first character
// in the lowest byte: the digits moved to the top (zeros before them), then combined in pairs.
inline uint64_t digitsValue(uint64_t chunk, int count) {
    uint64_t v = (chunk - 0x3030303030303030ull) << (8 * (8 - count));
    v = (v * 10 + (v >> 8)) & 0x00ff00ff00ff00ffull;
    v = (v * 100 + (v >> 16)) & 0x0000ffff0000ffffull;
    return (v * 10000 + (v >> 32)) & 0xffffffffull;
}

// The eight characters of `text` from `at` as such a word; false where fewer than eight follow or
// the machine does not store the lowest byte first.
inline bool eightCharacters(std::string_view text, size_t at, uint64_t& chunk) {
    if constexpr (std::endian::native != std::endian::little) return false;
    if (text.size() < at + 8) return false;
    std::memcpy(&chunk, text.data() + at, sizeof chunk);
    return true;
}

}  // namespace kerf::klartext
