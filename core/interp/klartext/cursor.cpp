#include "core/interp/klartext/cursor.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string>

namespace kerf::klartext {

bool Cursor::acceptChar(char c) {
    if (peek() != c) return false;
    ++m_pos;
    return true;
}

bool Cursor::acceptPrefix(std::string_view keyword) {
    skipBlanks();
    if (m_text.size() - m_pos < keyword.size()) return false;
    for (size_t i = 0; i < keyword.size(); ++i) {
        if (upper(m_text[m_pos + i]) != keyword[i]) return false;
    }
    m_pos += keyword.size();
    return true;
}

bool Cursor::peekKeyword(std::string_view keyword) {
    size_t saved = m_pos;
    bool found = acceptKeyword(keyword);
    m_pos = saved;
    return found;
}

bool Cursor::acceptKeyword(std::string_view keyword) {
    size_t saved = m_pos;
    if (!acceptPrefix(keyword)) return false;
    if (m_pos < m_text.size() && (isLetter(m_text[m_pos]) || m_text[m_pos] == '_')) {
        m_pos = saved;
        return false;
    }
    return true;
}

std::optional<double> Cursor::unsignedNumber() {
    skipBlanks();
    const char* const begin = m_text.data() + m_pos;
    const char* const end = m_text.data() + m_text.size();
    const char* p = begin;
    // Fast path: up to 15 significant digits and 15 decimals divide exactly-represented
    // integers, so the result is correctly rounded (as from_chars would give).
    uint64_t mantissa = 0;
    while (p != end && static_cast<unsigned>(*p - '0') < 10u) {
        mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
        ++p;
    }
    const char* const intEnd = p;
    int decimals = 0;
    if (p != end && (*p == '.' || *p == ',')) {
        const char* q = p + 1;
        while (q != end && static_cast<unsigned>(*q - '0') < 10u) {
            mantissa = mantissa * 10 + static_cast<unsigned>(*q - '0');
            ++q;
        }
        decimals = static_cast<int>(q - p - 1);
        // "5," followed by no digit is not a decimal comma ("REP 2,"); "5." is 5.0.
        if (decimals > 0 || *p == '.') p = q;
    }
    if (intEnd == begin && decimals == 0) return std::nullopt;
    const size_t length = static_cast<size_t>(p - begin);
    const auto digits = static_cast<int>(intEnd - begin) + decimals;
    if (digits <= 15 && decimals <= 15) {
        static constexpr double kPowers[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                             1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
        m_pos += length;
        return static_cast<double>(mantissa) / kPowers[decimals];
    }
    std::string copy(begin, p);
    for (char& c : copy) {
        if (c == ',') c = '.';
    }
    double value = 0.0;
    // A literal beyond the range of a double is no number (from_chars would leave 0).
    if (std::from_chars(copy.data(), copy.data() + copy.size(), value).ec != std::errc()) {
        return std::nullopt;
    }
    m_pos += length;
    return value;
}

std::optional<double> Cursor::signedNumber() {
    size_t saved = m_pos;
    char c = peek();
    double sign = 1.0;
    if (c == '+' || c == '-') {
        sign = c == '-' ? -1.0 : 1.0;
        ++m_pos;
    }
    auto value = unsignedNumber();
    if (!value) {
        m_pos = saved;
        return std::nullopt;
    }
    return sign * *value;
}

std::optional<long long> Cursor::unsignedInteger() {
    skipBlanks();
    size_t i = m_pos;
    long long value = 0;
    // Eighteen digits cannot overflow: check only beyond them (block numbers have up to seven).
    const size_t unchecked = std::min(m_text.size(), m_pos + 18);
    while (i < unchecked && isDigit(m_text[i])) {
        value = value * 10 + (m_text[i] - '0');
        ++i;
    }
    while (i < m_text.size() && isDigit(m_text[i])) {
        if (value > (std::numeric_limits<long long>::max() - 9) / 10) return std::nullopt;
        value = value * 10 + (m_text[i] - '0');
        ++i;
    }
    if (i == m_pos) return std::nullopt;
    m_pos = i;
    return value;
}

std::string_view Cursor::word() {
    skipBlanks();
    size_t start = m_pos;
    while (m_pos < m_text.size()) {
        char c = m_text[m_pos];
        if (!(isLetter(c) || isDigit(c) || c == '_' || c == '.' || c == '-')) break;
        ++m_pos;
    }
    return m_text.substr(start, m_pos - start);
}

std::optional<std::string_view> Cursor::quoted() {
    skipBlanks();
    if (m_pos >= m_text.size() || m_text[m_pos] != '"') return std::nullopt;
    size_t end = m_text.find('"', m_pos + 1);
    if (end == std::string_view::npos) return std::nullopt;
    std::string_view inside = m_text.substr(m_pos + 1, end - m_pos - 1);
    m_pos = end + 1;
    return inside;
}

std::string_view Cursor::restUntilComment() {
    skipBlanks();
    size_t start = m_pos;
    bool inString = false;
    size_t end = m_pos;
    while (end < m_text.size()) {
        char c = m_text[end];
        if (c == '"') inString = !inString;
        if (c == ';' && !inString) break;
        ++end;
    }
    m_pos = end;
    size_t trimmed = end;
    while (trimmed > start && (m_text[trimmed - 1] == ' ' || m_text[trimmed - 1] == '\t')) {
        --trimmed;
    }
    return m_text.substr(start, trimmed - start);
}

std::string_view Cursor::comment() {
    skipBlanks();
    if (m_pos >= m_text.size() || m_text[m_pos] != ';') return {};
    std::string_view c = m_text.substr(m_pos + 1);
    m_pos = m_text.size();
    return c;
}

}  // namespace kerf::klartext
