#include "core/interp/tnciso/iso_block_syntax.h"

#include "core/interp/klartext/cursor.h"

namespace kerf::tnciso {

using klartext::isDigit;
using klartext::upper;

bool IsoBlockSyntax::takesParameterLines(std::string_view text) const {
    size_t i = 0;
    auto blanks = [&] {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t'))
            ++i;
    };
    blanks();
    if (i < text.size() && text[i] == '/') ++i;
    blanks();
    if (i < text.size() && upper(text[i]) == 'N') {
        ++i;
        while (i < text.size() && isDigit(text[i]))
            ++i;
        blanks();
    }
    // GLOBAL DEF and PATTERN DEF take their parameter and pattern lines as in conversational
    // programs.
    if (isSpecialFunction(text, i)) return m_parser.takesParameterLines(text.substr(i));
    if (i + 3 >= text.size() || upper(text[i]) != 'G') return false;
    int g = 0;
    for (++i; i < text.size() && isDigit(text[i]) && g < 10000; ++i)
        g = g * 10 + (text[i] - '0');
    return g >= 120;
}

bool IsoBlockSyntax::parseBlock(const program::LogicalLine& isoLine,
                                const ConversationalBlock& block, klartext::ParsedBlock& out) {
    m_line.text = block.text();  // the block lives in m_translation until the next ISO block
    m_line.offset = isoLine.offset;
    m_line.nextOffset = isoLine.nextOffset;
    m_line.firstLine = isoLine.firstLine;
    m_line.segments.clear();
    for (size_t start : block.lineStarts()) {
        program::LineSegment segment;
        segment.joinedOffset = start;
        segment.line = isoLine.lineAt(block.isoOffset(start));
        m_line.segments.push_back(segment);
    }
    for (size_t s = 0; s < m_line.segments.size(); ++s) {
        const size_t end = s + 1 < m_line.segments.size() ? m_line.segments[s + 1].joinedOffset
                                                          : m_line.text.size();
        m_line.segments[s].text = m_line.text.substr(m_line.segments[s].joinedOffset,
                                                     end - m_line.segments[s].joinedOffset);
    }
    if (!m_parser.parse(m_line, out)) {
        m_problem = m_parser.problem();
        m_problem.offset = block.isoOffset(m_problem.offset);
        return false;
    }
    if (auto* cycle = std::get_if<klartext::CycleDefinition>(&out.statement)) {
        for (klartext::CycleParameter& p : cycle->parameters)
            p.offset = block.isoOffset(p.offset);
    }
    return true;
}

bool IsoBlockSyntax::parse(const program::LogicalLine& line, klartext::ParsedBlock& out) {
    out.statement = klartext::Empty{};
    out.more.clear();
    if (!m_translator.translate(line, m_translation)) {
        m_problem = m_translator.problem();
        return false;
    }
    if (m_translation.direct) {
        out.statement = std::move(*m_translation.direct);
    } else {
        const auto blocks = m_translation.blocks();
        for (size_t i = 0; i < blocks.size(); ++i) {
            if (!parseBlock(line, blocks[i], i == 0 ? out : m_parsed)) return false;
            if (i > 0) out.more.push_back(std::move(m_parsed.statement));
        }
    }
    out.blockNumber = m_translation.blockNumber;
    out.hidden = m_translation.hidden;
    return true;
}

}  // namespace kerf::tnciso
