#include "core/tables/detail/table_line.h"

namespace kerf::tables::detail {

std::vector<TableLine> splitLines(std::string_view bytes) {
    std::vector<TableLine> lines;
    size_t pos = 0;
    while (pos < bytes.size()) {
        size_t newline = bytes.find('\n', pos);
        TableLine line;
        if (newline == std::string_view::npos) {
            line.text.assign(bytes.substr(pos));
            line.ending = LineEnding::None;
            pos = bytes.size();
        } else {
            size_t end = newline;
            line.ending = LineEnding::Lf;
            if (end > pos && bytes[end - 1] == '\r') {
                --end;
                line.ending = LineEnding::CrLf;
            }
            line.text.assign(bytes.substr(pos, end - pos));
            pos = newline + 1;
        }
        lines.push_back(std::move(line));
    }
    return lines;
}

std::string_view endingText(LineEnding ending) {
    switch (ending) {
        case LineEnding::None:
            return "";
        case LineEnding::Lf:
            return "\n";
        case LineEnding::CrLf:
            return "\r\n";
    }
    return "";
}

std::string_view trimSpaces(std::string_view text) {
    size_t begin = text.find_first_not_of(" \t");
    if (begin == std::string_view::npos) return {};
    size_t end = text.find_last_not_of(" \t");
    return text.substr(begin, end - begin + 1);
}

}  // namespace kerf::tables::detail
