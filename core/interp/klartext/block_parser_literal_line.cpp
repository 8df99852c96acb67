// The literal straight line "L X+1.5 Y-2 Z+0.25 R0 F1500 M3", the block CAM programs consist of,
// scanned in one pass. Anything else (Q parameters, formulas, incremental or polar words, lower
// case, M functions with parameters, a word written twice ...) is left to the general parser,
// which then parses the block from its start: this pass accepts only blocks it reads exactly as
// the general parser does, so the result is the same statement either way.
#include <bit>
#include <cstdint>
#include <cstring>
#include <variant>

#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/digit_run.h"

namespace kerf::klartext {

namespace {

bool endsWord(const char* p, const char* end) {
    return p == end || *p == ' ' || *p == '\t' || *p == ';';
}

// A literal "ddd.dddd" that ends within the eight bytes at p, read at once: its digits as one
// integer, how many of them are decimals, and where it ends (nullptr: it is no number). False
// when it does not end there or eight bytes cannot be read; the caller then reads it byte by
// byte. Near the end of a line of eight bytes or more, the line's last eight bytes are read and
// shifted, so that zeros follow its end.
bool shortLiteral(const char*& p, const char* begin, const char* end, uint64_t& mantissa,
                  int& decimals) {
    if constexpr (std::endian::native != std::endian::little) return false;
    uint64_t chunk;
    if (end - p >= 8) {
        std::memcpy(&chunk, p, sizeof chunk);
    } else if (end - begin >= 8 && p != end) {
        std::memcpy(&chunk, end - 8, sizeof chunk);
        chunk >>= 8 * (8 - (end - p));
    } else {
        return false;
    }
    const uint64_t stops = notDigits(chunk);
    if (stops == 0) return false;
    const int integral = std::countr_zero(stops) >> 3;
    const auto separator = static_cast<char>(chunk >> (8 * integral));
    int length = integral;
    decimals = 0;
    if (separator == '.' || separator == ',') {
        const uint64_t after = stops & (stops - 1);
        if (after == 0) return false;
        length = (std::countr_zero(after) >> 3) - 1;
        decimals = length - integral;
        // The decimals moved down over the separator.
        const uint64_t low = integral == 0 ? 0 : chunk & (~0ull >> (64 - 8 * integral));
        chunk = low | ((chunk >> (8 * (integral + 1))) << (8 * integral));
        p += 1;
    }
    p += length;
    // No digit at all, "5," (no decimal comma) or ",5" (the general parser refuses it).
    if (length == 0 || (separator == ',' && (decimals == 0 || integral == 0))) {
        p = nullptr;
        return true;
    }
    mantissa = digitsValue(chunk, length);
    return true;
}

// An unsigned literal at `at` as Cursor::unsignedNumber reads it (up to 15 digits, '.' or ','),
// computed the same way; false for anything it would read differently or not at all.
bool literal(const char*& at, const char* begin, const char* end, double& value) {
    static constexpr double kPowers[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                         1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    const char* p = at;
    uint64_t mantissa = 0;
    int decimals = 0;
    if (shortLiteral(p, begin, end, mantissa, decimals)) {
        if (p == nullptr) return false;
    } else {
        while (p != end && static_cast<unsigned>(*p - '0') < 10u)
            mantissa = mantissa * 10 + static_cast<unsigned>(*p++ - '0');
        const auto integral = static_cast<int>(p - at);
        if (p != end && (*p == '.' || *p == ',')) {
            const char* const separator = p++;
            while (p != end && static_cast<unsigned>(*p - '0') < 10u)
                mantissa = mantissa * 10 + static_cast<unsigned>(*p++ - '0');
            decimals = static_cast<int>(p - separator - 1);
            // "5," is no decimal comma; ",5" is left to the general parser, which refuses it.
            if (*separator == ',' && (decimals == 0 || integral == 0)) return false;
        }
        if (integral + decimals == 0 || integral + decimals > 15) return false;
    }
    at = p;
    value = static_cast<double>(mantissa) / kPowers[decimals];
    return endsWord(p, end);
}

}  // namespace

bool BlockParser::parseLiteralLine(std::string_view text, size_t at, ParsedBlock& out) {
    const char* p = text.data() + at;
    const char* const begin = text.data();
    const char* const end = text.data() + text.size();
    // Reuse the statement's storage when the previous block was a line too: clearing the words it
    // set leaves the same state as a new one.
    auto* reused = std::get_if<LinearBlock>(&out.statement);
    LinearBlock& block = reused != nullptr ? *reused : out.statement.emplace<LinearBlock>();
    if (reused != nullptr) {
        for (auto bits = static_cast<unsigned>(block.coords.present); bits != 0; bits &= bits - 1)
            block.coords.axes[static_cast<size_t>(std::countr_zero(bits))] = AxisWord{};
        block.coords.present = 0;
        for (uint8_t i = 0; i < block.words.m.count; ++i)
            block.words.m.list[i] = MWord{};
        block.words.m.count = 0;
        block.words.comp = CompWord::None;
        block.words.feed = FeedWord{};
    }
    for (;;) {
        while (p != end && (*p == ' ' || *p == '\t'))
            ++p;
        if (p == end || *p == ';') break;
        const char c = *p++;
        if (c >= 'A' && c <= 'Z' && axisFromLetter(c)) {
            const auto index = static_cast<size_t>(*axisFromLetter(c));
            const AxisMask bit = axisBit(static_cast<Axis>(index));
            if ((block.coords.present & bit) != 0) return false;
            double sign = 1.0;
            if (p != end && (*p == '+' || *p == '-')) sign = *p++ == '-' ? -1.0 : 1.0;
            double value = 0.0;
            if (!literal(p, begin, end, value)) return false;
            AxisWord& word = block.coords.axes[index];
            word.present = true;
            word.value = sign * value;
            block.coords.present |= bit;
        } else if (c == 'R' && p != end && (*p == '0' || *p == 'L' || *p == 'R') &&
                   endsWord(p + 1, end)) {
            block.words.comp = *p == '0'   ? CompWord::Off
                               : *p == 'L' ? CompWord::Left
                                           : CompWord::Right;
            ++p;
        } else if (c == 'F' && end - p >= 3 && p[0] == 'M' && p[1] == 'A' && p[2] == 'X' &&
                   endsWord(p + 3, end)) {
            block.words.feed.kind = FeedWord::Kind::Max;
            p += 3;
        } else if (c == 'F' && p != end && (static_cast<unsigned>(*p - '0') < 10u || *p == '.')) {
            block.words.feed.kind = FeedWord::Kind::Value;
            if (!literal(p, begin, end, block.words.feed.value)) return false;
        } else if (c == 'M' && p != end && static_cast<unsigned>(*p - '0') < 10u &&
                   block.words.m.count < block.words.m.list.size()) {
            int number = 0;
            const char* const digits = p;
            while (p != end && static_cast<unsigned>(*p - '0') < 10u && p - digits < 5)
                number = number * 10 + (*p++ - '0');
            // M94, M118 and M120 read words after them; more than four digits is an error.
            if (number > 9999 || number == 94 || number == 118 || number == 120 ||
                !endsWord(p, end))
                return false;
            block.words.m.list[block.words.m.count++].number = number;
        } else {
            return false;
        }
    }
    // Without coordinates or compensation the block is an M function block.
    return block.coords.present != 0 || block.words.comp != CompWord::None;
}

}  // namespace kerf::klartext
