#include "core/interp/klartext/block_reader.h"

#include <string>

#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/cursor.h"

namespace kerf::klartext {

namespace {

// "  Q200=2 ;..." or "  QS500=..." : an indented cycle parameter line.
bool isIndentedParameterLine(std::string_view line) {
    size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
    if (i == 0 || i >= line.size() || upper(line[i]) != 'Q') return false;
    ++i;
    if (i < line.size() && upper(line[i]) == 'S') ++i;
    size_t digits = i;
    while (i < line.size() && isDigit(line[i]))
        ++i;
    if (i == digits) return false;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
    return i < line.size() && line[i] == '=';
}

// "  POS2 (X+40 Y+30 Z+0)": an indented element of a multi-line PATTERN DEF.
bool isIndentedPatternLine(std::string_view line) {
    size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
    if (i == 0) return false;
    size_t end = i;
    while (end < line.size() && isLetter(line[end]))
        ++end;
    std::string word(line.substr(i, end - i));
    for (char& c : word)
        c = upper(c);
    return word == "POS" || word == "ROW" || word == "PAT" || word == "FRAME" || word == "CIRC" ||
           word == "PITCHCIRC";
}

// "N5 PATTERN DEF": a DIN/ISO block without its block number, whose head word then follows.
std::string_view withoutIsoNumber(std::string_view text) {
    size_t at = text.find_first_not_of(" \t");
    if (at == std::string_view::npos || upper(text[at]) != 'N') return text;
    ++at;
    while (at < text.size() && isDigit(text[at]))
        ++at;
    return text.substr(at);
}

}  // namespace

bool BlockParser::takesParameterLines(std::string_view text) const {
    std::string_view head = headWord(text);
    if (head.size() < 3 || head.size() > 7) return false;
    std::string upperHead(head);
    for (char& c : upperHead)
        c = upper(c);
    return upperHead == "CYCL" || upperHead == "GLOBAL" || upperHead == "PATTERN" ||
           upperHead == "TCH";
}

bool BlockReader::next(program::LogicalLine& line) {
    if (!m_lines.next(line)) return false;
    const char next = m_lines.peekByte();
    if (line.segments.size() == 1 && (next == ' ' || next == '\t')) {
        static const BlockParser kConversational(nullptr);
        const BlockSyntax& syntax = m_syntax != nullptr ? *m_syntax : kConversational;
        if (syntax.takesParameterLines(line.text)) {
            const std::string_view head = BlockParser::headWord(withoutIsoNumber(line.text));
            const bool pattern = !head.empty() && upper(head[0]) == 'P';  // PATTERN DEF
            while (isIndentedParameterLine(m_lines.peekLine()) ||
                   (pattern && isIndentedPatternLine(m_lines.peekLine()))) {
                m_lines.appendNextLine(line);
            }
        }
    }
    return true;
}

}  // namespace kerf::klartext
