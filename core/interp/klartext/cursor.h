#pragma once

#include <algorithm>
#include <optional>
#include <string_view>

namespace kerf::klartext {

// Scans one block of conversational text. Keywords match case-insensitively at word boundaries;
// numbers accept a decimal comma (files from controls set to German or Portuguese).
class Cursor {
public:
    explicit Cursor(std::string_view text, size_t position = 0)
        : m_text(text), m_pos(std::min(position, text.size())) {}

    size_t position() const { return m_pos; }
    void setPosition(size_t position) { m_pos = std::min(position, m_text.size()); }
    std::string_view text() const { return m_text; }
    std::string_view rest() const { return m_text.substr(m_pos); }

    // These three are inline: the parser calls them several times per word.
    void skipBlanks() {
        while (m_pos < m_text.size() && (m_text[m_pos] == ' ' || m_text[m_pos] == '\t'))
            ++m_pos;
    }
    // True at the end of the text or at a ';' comment (after blanks).
    bool atEnd() {
        skipBlanks();
        return m_pos >= m_text.size() || m_text[m_pos] == ';';
    }
    char peek() {  // after blanks; '\0' at the end
        skipBlanks();
        return m_pos < m_text.size() ? m_text[m_pos] : '\0';
    }
    char peekRaw() const { return m_pos < m_text.size() ? m_text[m_pos] : '\0'; }
    bool acceptChar(char c);
    // Matches `keyword` followed by a non-letter (digits may follow directly: "LBL1", "FN0").
    bool acceptKeyword(std::string_view keyword);
    // Matches `keyword` followed by anything (for prefixes such as "IX" or "FQ").
    bool acceptPrefix(std::string_view keyword);
    bool peekKeyword(std::string_view keyword);
    // Unsigned decimal number (digits with '.' or ',' as separator).
    std::optional<double> unsignedNumber();
    // Number with optional sign, blanks allowed after the sign ("X + 0").
    std::optional<double> signedNumber();
    std::optional<long long> unsignedInteger();
    // A run of letters, digits, '_' and '.' (for names and keywords).
    std::string_view word();
    // A "quoted" string; the position is left after the closing quote.
    std::optional<std::string_view> quoted();
    // The rest of the block up to a ';' comment, trimmed.
    std::string_view restUntilComment();
    // The comment text after ';' if the cursor is at one.
    std::string_view comment();

private:
    std::string_view m_text;
    size_t m_pos;
};

inline bool isLetter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
inline bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
inline char upper(char c) {
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

}  // namespace kerf::klartext
