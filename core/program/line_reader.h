#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::program {

// The most characters one block may hold (its lines joined), in every dialect: parsing costs
// tens of bytes a character, so an unbounded line of a damaged or generated file could exhaust
// memory. Real blocks hold a few hundred at most.
inline constexpr size_t kMaxBlockCharacters = 60000;

// One physical line of a logical block, with the continuation mark removed.
struct LineSegment {
    std::string_view text;
    uint32_t line = 0;        // 1-based line in the file
    size_t joinedOffset = 0;  // where the segment starts in LogicalLine::text
};

// A block as the control sees it: one line, or several joined by a trailing '~' (TNC). Reused by
// the reader to avoid allocating per line.
struct LogicalLine {
    std::string_view text;  // the segments joined (a view into the file for single lines)
    std::vector<LineSegment> segments;
    size_t offset = 0;      // byte offset of the first line in the file
    size_t nextOffset = 0;  // byte offset of the line after the block
    uint32_t firstLine = 0;

    // 1-based line and column in the file of an offset in `text`.
    uint32_t lineAt(size_t textOffset) const;
    uint32_t columnAt(size_t textOffset) const;

    std::string joined;  // storage for multi-line text
};

// Reads logical lines from UTF-8 text with LF, CRLF or CR line ends.
class LineReader {
public:
    explicit LineReader(std::string_view text, size_t offset = 0, uint32_t line = 1)
        : m_text(text), m_offset(offset), m_line(line) {}

    // False at the end of the text. `joinContinuations` = false reads physical lines only.
    bool next(LogicalLine& out, bool joinContinuations = true);
    // Appends the next physical line to `out` as a further segment (used for cycle parameter lines
    // written on their own lines without '~').
    bool appendNextLine(LogicalLine& out);
    // The next physical line without consuming it.
    std::string_view peekLine() const;
    char peekByte() const { return m_offset < m_text.size() ? m_text[m_offset] : '\0'; }

    size_t offset() const { return m_offset; }
    uint32_t line() const { return m_line; }
    void seek(size_t offset, uint32_t line) {
        m_offset = offset;
        m_line = line;
        m_nextLf = kUnknown;
    }

private:
    std::string_view readPhysical(bool& continued);
    void finishJoin(LogicalLine& out);

    static constexpr size_t kUnknown = static_cast<size_t>(-1);

    std::string_view m_text;
    size_t m_offset;
    uint32_t m_line;
    size_t m_nextLf = kUnknown;  // the first LF at or after m_offset (m_text.size(): none)
};

}  // namespace kerf::program
