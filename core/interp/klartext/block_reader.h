#pragma once

#include "core/interp/klartext/block_syntax.h"
#include "core/program/line_reader.h"

namespace kerf::klartext {

// Reads conversational blocks: logical lines ('~' continuations joined), plus the manual's layout
// of cycle definitions, where each "Qnnn=value ;comment" line is indented below the CYCL DEF line
// without a continuation mark. `syntax` says which blocks take such lines (nullptr:
// conversational).
class BlockReader {
public:
    explicit BlockReader(std::string_view text, const BlockSyntax* syntax = nullptr)
        : m_lines(text), m_syntax(syntax) {}

    bool next(program::LogicalLine& line);
    void seek(size_t offset, uint32_t line) { m_lines.seek(offset, line); }
    size_t offset() const { return m_lines.offset(); }
    uint32_t line() const { return m_lines.line(); }

private:
    program::LineReader m_lines;
    const BlockSyntax* m_syntax;
};

}  // namespace kerf::klartext
