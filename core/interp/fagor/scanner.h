#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace kerf::fagor {

inline bool isUpper(char c) {
    return c >= 'A' && c <= 'Z';
}
inline bool isLower(char c) {
    return c >= 'a' && c <= 'z';
}
inline bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
// ESC, EOT, SUB and ETX end a file sent to a peripheral (serial parameter EOFCHR).
inline bool isEndOfFileChar(char c) {
    return c == 0x1B || c == 0x04 || c == 0x1A || c == 0x03;
}

// A decimal number as written: its value and how many digits it has on each side of the point
// (leading zeros of the integral part not counted), for the manual's formats such as 5.5.
struct ScannedNumber {
    double value = 0.0;
    uint8_t intDigits = 0;
    uint8_t decDigits = 0;
};

// Scans one block of FAGOR text. Blanks are spaces and tabs; the text ends at its end, at a ';'
// comment or at an end-of-file character.
class Scanner {
public:
    explicit Scanner(std::string_view text, size_t position = 0) : m_text(text), m_pos(position) {}

    size_t position() const { return m_pos; }
    void setPosition(size_t position) {
        m_pos = position < m_text.size() ? position : m_text.size();
    }
    std::string_view text() const { return m_text; }

    void skipBlanks() {
        while (m_pos < m_text.size() && (m_text[m_pos] == ' ' || m_text[m_pos] == '\t'))
            ++m_pos;
    }
    // After blanks: the next character, '\0' at the end of the text.
    char peek() {
        skipBlanks();
        return m_pos < m_text.size() ? m_text[m_pos] : '\0';
    }
    char peekRaw() const { return m_pos < m_text.size() ? m_text[m_pos] : '\0'; }
    char peekAt(size_t ahead) const {
        return m_pos + ahead < m_text.size() ? m_text[m_pos + ahead] : '\0';
    }
    void advance(size_t n = 1) { m_pos = m_pos + n < m_text.size() ? m_pos + n : m_text.size(); }
    bool accept(char c) {
        if (peek() != c) return false;
        ++m_pos;
        return true;
    }
    // True at the end, at ';' or at an end-of-file character (after blanks).
    bool atEnd() {
        const char c = peek();
        return c == '\0' || c == ';' || isEndOfFileChar(c);
    }
    // Unsigned decimal "ddd.ddd", ".5" or "5."; false (position unchanged) if there is none.
    bool unsignedNumber(ScannedNumber& out);
    // Unsigned integer of at most 18 digits; false if there is none.
    bool unsignedInteger(int64_t& out, uint8_t& digits);
    // A run of upper-case letters.
    std::string_view letters();

private:
    std::string_view m_text;
    size_t m_pos;
};

}  // namespace kerf::fagor
