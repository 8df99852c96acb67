#include "core/tables/detail/description_block.h"

#include <charconv>
#include <string_view>

namespace kerf::tables::detail {

namespace {

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

// Change of parenthesis depth over one line, ignoring quoted text.
int parenthesisBalance(std::string_view text) {
    int balance = 0;
    bool quoted = false;
    for (char c : text) {
        if (c == '"') quoted = !quoted;
        if (quoted) continue;
        if (c == '(') ++balance;
        if (c == ')') --balance;
    }
    return balance;
}

// "NAME = WMAT" or `key:="KEY",` -> ("NAME", "WMAT") or ("key", "KEY").
bool splitAttribute(std::string_view line, std::string_view& key, std::string_view& value) {
    line = trimSpaces(line);
    size_t equals = line.find('=');
    if (equals == std::string_view::npos || equals == 0) return false;
    size_t keyEnd = line[equals - 1] == ':' ? equals - 1 : equals;
    key = trimSpaces(line.substr(0, keyEnd));
    value = trimSpaces(line.substr(equals + 1));
    if (!value.empty() && value.back() == ',')
        value = trimSpaces(value.substr(0, value.size() - 1));
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
        value = value.substr(1, value.size() - 2);
    }
    return !key.empty();
}

int toInt(std::string_view text) {
    int value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

void applyAttribute(DescribedColumn& column, std::string_view key, std::string_view value) {
    if (key == "TYPE") {  // .CDT: N numeric, C characters
        column.format.kind = value == "N" ? CellKind::Number : CellKind::Text;
    } else if (key == "DEC") {
        column.format.defaultDecimals = toInt(value);
    } else if (key == "unit") {  // TableDescription: INT, TEXT or a physical unit
        if (value == "TEXT") {
            column.format.kind = CellKind::Text;
        } else {
            column.format.kind = value == "INT" ? CellKind::Integer : CellKind::Number;
        }
    } else if (key == "initial") {
        column.format.defaultValue.assign(value);
        column.format.explicitSign = startsWith(value, "+");
    }
}

}  // namespace

size_t descriptionBlockLength(const std::vector<TableLine>& lines, size_t first) {
    std::string_view text = lines[first].text;
    if (startsWith(text, "#STRUCTBEGIN")) {
        for (size_t i = first + 1; i < lines.size(); ++i) {
            if (startsWith(lines[i].text, "#STRUCTEND")) return i - first + 1;
        }
        return lines.size() - first;
    }
    if (startsWith(text, "TableDescription")) {
        int depth = 0;
        for (size_t i = first; i < lines.size(); ++i) {
            depth += parenthesisBalance(lines[i].text);
            if (depth <= 0 && i > first) return i - first + 1;
            if (depth <= 0 && lines[i].text.find('(') != std::string::npos) return 1;
        }
        return lines.size() - first;
    }
    return 0;
}

std::vector<DescribedColumn> readColumnDescriptions(const std::vector<TableLine>& lines,
                                                    size_t first, size_t count) {
    std::vector<DescribedColumn> columns;
    for (size_t i = first; i < first + count && i < lines.size(); ++i) {
        std::string_view key;
        std::string_view value;
        if (!splitAttribute(lines[i].text, key, value)) continue;
        if (key == "NAME" || key == "key") {
            columns.push_back(DescribedColumn{std::string(value), ColumnFormat{}});
        } else if (!columns.empty()) {
            applyAttribute(columns.back(), key, value);
        }
    }
    return columns;
}

}  // namespace kerf::tables::detail
