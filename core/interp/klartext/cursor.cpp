#include "core/interp/klartext/cursor.h"

#include <charconv>
#include <string>

namespace kerf::klartext {

void Cursor::skipBlanks() {
    while (m_pos < m_text.size() && (m_text[m_pos] == ' ' || m_text[m_pos] == '\t')) ++m_pos;
}

bool Cursor::atEnd() {
    skipBlanks();
    return m_pos >= m_text.size() || m_text[m_pos] == ';';
}

char Cursor::peek() {
    skipBlanks();
    return m_pos < m_text.size() ? m_text[m_pos] : '\0';
}

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
    size_t start = m_pos;
    size_t i = m_pos;
    while (i < m_text.size() && isDigit(m_text[i])) ++i;
    size_t intEnd = i;
    bool fraction = false;
    if (i < m_text.size() && (m_text[i] == '.' || m_text[i] == ',') && i + 1 <= m_text.size()) {
        size_t j = i + 1;
        while (j < m_text.size() && isDigit(m_text[j])) ++j;
        // "5," followed by nothing numeric is not a decimal comma ("REP 2,"); "5." is 5.0.
        if (j > i + 1 || m_text[i] == '.') {
            fraction = true;
            i = j;
        }
    }
    if (intEnd == start && !(fraction && i > intEnd + 1)) return std::nullopt;
    double value = 0.0;
    if (!fraction || m_text[intEnd] == '.') {
        auto result = std::from_chars(m_text.data() + start, m_text.data() + i, value);
        if (result.ec != std::errc()) return std::nullopt;
        // from_chars stops before a trailing '.', which belongs to the number too.
        m_pos = i;
        return value;
    }
    std::string copy(m_text.substr(start, i - start));
    copy[intEnd - start] = '.';
    auto result = std::from_chars(copy.data(), copy.data() + copy.size(), value);
    if (result.ec != std::errc()) return std::nullopt;
    m_pos = i;
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
    size_t start = m_pos;
    long long value = 0;
    auto result = std::from_chars(m_text.data() + m_pos, m_text.data() + m_text.size(), value);
    if (result.ec != std::errc() || result.ptr == m_text.data() + start || value < 0) {
        return std::nullopt;
    }
    m_pos = static_cast<size_t>(result.ptr - m_text.data());
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
