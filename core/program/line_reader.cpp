#include "core/program/line_reader.h"

#include <cstring>

#include "core/program/source_text.h"

namespace kerf::program {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

// Strips a trailing '~' (and the blanks before it); true if there was one.
bool stripContinuation(std::string_view& line) {
    size_t end = line.size();
    while (end > 0 && isBlank(line[end - 1]))
        --end;
    if (end == 0 || line[end - 1] != '~') return false;
    --end;
    while (end > 0 && isBlank(line[end - 1]))
        --end;
    line = line.substr(0, end);
    return true;
}

}  // namespace

uint32_t LogicalLine::lineAt(size_t textOffset) const {
    uint32_t line = firstLine;
    for (const LineSegment& s : segments) {
        if (s.joinedOffset > textOffset) break;
        line = s.line;
    }
    return line;
}

uint32_t LogicalLine::columnAt(size_t textOffset) const {
    const LineSegment* segment = nullptr;
    for (const LineSegment& s : segments) {
        if (s.joinedOffset > textOffset) break;
        segment = &s;
    }
    if (segment == nullptr) return columnOf(text, textOffset);
    return columnOf(segment->text, textOffset - segment->joinedOffset);
}

std::string_view LineReader::readPhysical(bool& continued) {
    const char* begin = m_text.data() + m_offset;
    const size_t left = m_text.size() - m_offset;
    if (m_nextLf == kUnknown || m_nextLf < m_offset) {
        // Remembered: in a file with CR line ends alone, searching for LF on every line would
        // scan the rest of the file each time.
        const void* lf = std::memchr(begin, '\n', left);
        m_nextLf =
            lf ? static_cast<size_t>(static_cast<const char*>(lf) - m_text.data()) : m_text.size();
    }
    const bool newline = m_nextLf < m_text.size();
    size_t length = m_nextLf - m_offset;
    size_t consumed = newline ? length + 1 : length;
    if (const void* cr = std::memchr(begin, '\r', length)) {
        auto crAt = static_cast<size_t>(static_cast<const char*>(cr) - begin);
        if (crAt + 1 == length && newline) {
            length = crAt;  // CRLF
        } else {
            length = crAt;  // a lone CR (old Macintosh files) ends the line
            consumed = crAt + 1;
        }
    }
    std::string_view line(begin, length);
    m_offset += consumed;
    ++m_line;
    continued = stripContinuation(line);
    return line;
}

bool LineReader::next(LogicalLine& out, bool joinContinuations) {
    if (m_offset >= m_text.size()) return false;
    out.segments.clear();
    out.offset = m_offset;
    out.firstLine = m_line;
    bool continued = false;
    std::string_view line = readPhysical(continued);
    out.segments.push_back({line, out.firstLine, 0});
    while (continued && joinContinuations && m_offset < m_text.size()) {
        uint32_t lineNumber = m_line;
        std::string_view more = readPhysical(continued);
        out.segments.push_back({more, lineNumber, 0});
    }
    finishJoin(out);
    out.nextOffset = m_offset;
    return true;
}

bool LineReader::appendNextLine(LogicalLine& out) {
    if (m_offset >= m_text.size()) return false;
    bool continued = false;
    uint32_t lineNumber = m_line;
    std::string_view line = readPhysical(continued);
    out.segments.push_back({line, lineNumber, 0});
    finishJoin(out);
    out.nextOffset = m_offset;
    return true;
}

std::string_view LineReader::peekLine() const {
    LineReader copy = *this;
    bool continued = false;
    if (copy.m_offset >= copy.m_text.size()) return {};
    return copy.readPhysical(continued);
}

void LineReader::finishJoin(LogicalLine& out) {
    if (out.segments.size() == 1) {
        out.text = out.segments.front().text;
        return;
    }
    out.joined.clear();
    for (LineSegment& segment : out.segments) {
        if (!out.joined.empty() && !isBlank(out.joined.back()) && !segment.text.empty() &&
            !isBlank(segment.text.front())) {
            out.joined += ' ';
        }
        segment.joinedOffset = out.joined.size();
        out.joined.append(segment.text);
    }
    // The views of the segments point into the file; `text` into the joined copy.
    out.text = out.joined;
}

}  // namespace kerf::program
