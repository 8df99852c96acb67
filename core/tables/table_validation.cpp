#include "core/tables/table_validation.h"

#include <charconv>
#include <cmath>
#include <map>
#include <string>

#include "core/tables/tnc_number.h"

namespace kerf::tables {

namespace {

bool isWholeNumber(double value) {
    return std::floor(value) == value;
}

// "5" -> {5, 0}; "5.1" -> {5, 1} when indexes are allowed.
std::optional<RowKey> parseKey(std::string_view text, bool allowIndex) {
    auto value = parseTncNumber(text);
    if (!value || *value < 0 || *value > 2147483647.0) return std::nullopt;
    RowKey key;
    key.number = static_cast<int>(std::floor(*value));
    if (isWholeNumber(*value)) return key;
    if (!allowIndex) return std::nullopt;
    size_t separator = text.find_first_of(".,");
    std::string_view digits = text.substr(separator + 1);
    auto result = std::from_chars(digits.data(), digits.data() + digits.size(), key.index);
    if (result.ec != std::errc() || result.ptr != digits.data() + digits.size())
        return std::nullopt;
    return key;
}

std::string keyText(RowKey key) {
    std::string text = std::to_string(key.number);
    if (key.index != 0) text += "." + std::to_string(key.index);
    return text;
}

}  // namespace

DiagnosticList checkNumericCells(const TncTable& table) {
    DiagnosticList errors;
    for (size_t column = 0; column < table.columns().size(); ++column) {
        const ColumnFormat& format = table.columnFormat(column);
        if (!format.numeric()) continue;
        const std::string& name = table.columns()[column].name;
        for (size_t row = 0; row < table.rowCount(); ++row) {
            std::string_view text = table.cell(row, column);
            if (text.empty()) continue;
            auto value = parseTncNumber(text);
            if (!value) {
                errors.push_back(table.cellError(
                    row, column, KERF_TR_NOOP("column {1} needs a number, not \"{2}\""),
                    {name, std::string(text)}));
            } else if (format.kind == CellKind::Integer && !isWholeNumber(*value)) {
                errors.push_back(table.cellError(
                    row, column, KERF_TR_NOOP("column {1} needs a whole number, not \"{2}\""),
                    {name, std::string(text)}));
            }
        }
    }
    return errors;
}

MaybeError requireColumn(const TncTable& table, std::string_view name) {
    if (table.findColumn(name)) return std::nullopt;
    return table.headerError(KERF_TR_NOOP("the table has no column {1}"), {std::string(name)});
}

std::vector<std::optional<RowKey>> readRowKeys(const TncTable& table, size_t keyColumn,
                                               bool allowIndex, DiagnosticList& errors) {
    std::vector<std::optional<RowKey>> keys(table.rowCount());
    std::map<std::pair<int, int>, size_t> seen;
    const std::string& name = table.columns().at(keyColumn).name;
    for (size_t row = 0; row < table.rowCount(); ++row) {
        std::string_view text = table.cell(row, keyColumn);
        if (text.empty()) {
            errors.push_back(table.cellError(row, keyColumn,
                                             KERF_TR_NOOP("the key column {1} is empty"), {name}));
            continue;
        }
        auto key = parseKey(text, allowIndex);
        if (!key) {
            errors.push_back(table.cellError(
                row, keyColumn, KERF_TR_NOOP("column {1} needs a whole number >= 0, not \"{2}\""),
                {name, std::string(text)}));
            continue;
        }
        auto [it, inserted] = seen.emplace(std::make_pair(key->number, key->index), row);
        if (!inserted) {
            errors.push_back(table.cellError(
                row, keyColumn, KERF_TR_NOOP("{1} {2} appears twice (first in line {3})"),
                {name, keyText(*key), std::to_string(table.rowLineNumber(it->second))}));
            continue;
        }
        keys[row] = key;
    }
    return keys;
}

size_t sortedInsertPosition(const std::vector<std::optional<RowKey>>& keys, RowKey key) {
    for (size_t row = 0; row < keys.size(); ++row) {
        if (keys[row] && std::make_pair(keys[row]->number, keys[row]->index) >
                             std::make_pair(key.number, key.index)) {
            return row;
        }
    }
    return keys.size();
}

}  // namespace kerf::tables
