#include "core/tables/detail/begin_line.h"

#include "core/tables/detail/table_line.h"

namespace kerf::tables::detail {

namespace {

constexpr std::string_view kBegin = "BEGIN";

size_t skipSpaces(std::string_view text, size_t pos) {
    while (pos < text.size() && text[pos] == ' ')
        ++pos;
    return pos;
}

size_t wordEnd(std::string_view text, size_t pos, std::string_view stops) {
    while (pos < text.size() && stops.find(text[pos]) == std::string_view::npos)
        ++pos;
    return pos;
}

Diagnostic beginError(const std::string& fileName, size_t offset, const char* message) {
    return Diagnostic::make(Severity::Error, "table", fileName, 1,
                            static_cast<uint32_t>(offset + 1), message);
}

}  // namespace

Expected<BeginLine> parseBeginLine(std::string_view text, const std::string& fileName) {
    if (text.substr(0, kBegin.size()) != kBegin ||
        (text.size() > kBegin.size() && text[kBegin.size()] != ' ')) {
        return beginError(fileName, 0, KERF_TR_NOOP("the table does not start with a BEGIN line"));
    }
    BeginLine line;
    size_t pos = skipSpaces(text, kBegin.size());
    size_t end = wordEnd(text, pos, " .");
    line.name.assign(text.substr(pos, end - pos));
    if (line.name.empty()) {
        return beginError(fileName, pos, KERF_TR_NOOP("the BEGIN line names no table"));
    }
    pos = skipSpaces(text, end);
    if (pos >= text.size() || text[pos] != '.') {
        return beginError(fileName, pos, KERF_TR_NOOP("the BEGIN line gives no file type"));
    }
    end = wordEnd(text, pos + 1, " ");
    line.extension.assign(text.substr(pos + 1, end - pos - 1));
    if (line.extension.empty()) {
        return beginError(fileName, pos, KERF_TR_NOOP("the BEGIN line gives no file type"));
    }
    pos = skipSpaces(text, end);
    end = wordEnd(text, pos, " ");
    std::string_view word = text.substr(pos, end - pos);
    if (word == "MM" || word == "INCH") {
        line.unit.assign(word);
        pos = skipSpaces(text, end);
    }
    line.rest.assign(trimSpaces(text.substr(pos)));
    return line;
}

}  // namespace kerf::tables::detail
