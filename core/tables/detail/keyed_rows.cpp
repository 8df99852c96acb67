#include "core/tables/detail/keyed_rows.h"

namespace kerf::tables::detail {

Expected<size_t> rowOfKey(const std::vector<std::optional<RowKey>>& keys, const TncTable& table,
                          int number, const char* messageTemplate) {
    for (size_t row = 0; row < keys.size(); ++row) {
        if (keys[row] && keys[row]->number == number) return row;
    }
    return Diagnostic::make(Severity::Error, "table", table.fileName(), 0, 0, messageTemplate,
                            std::to_string(number));
}

MaybeError setAxisCell(TncTable& table, size_t row, char axis, std::optional<double> value) {
    auto column = table.findColumn(std::string_view(&axis, 1));
    if (!column) {
        return table.headerError(KERF_TR_NOOP("the table has no column {1}"),
                                 {std::string(1, axis)});
    }
    if (!value) return table.setCell(row, *column, "");
    return table.setNumber(row, *column, *value);
}

MaybeError insertKeyedRow(TncTable& table, size_t keyColumn,
                          const std::vector<std::optional<RowKey>>& keys, int number) {
    const std::string key = std::to_string(number);
    if (number < 0) {
        return table.headerError(KERF_TR_NOOP("column {1} needs a whole number >= 0, not \"{2}\""),
                                 {table.columns().at(keyColumn).name, key});
    }
    auto row = table.insertRow(sortedInsertPosition(keys, RowKey{number, 0}),
                               keyColumn == 0 ? key : std::string());
    if (!row) return row.error();
    if (keyColumn == 0) return std::nullopt;
    return table.setCell(*row, keyColumn, key);
}

std::vector<std::optional<RowKey>> validateKeyedTable(const TncTable& table,
                                                      std::string_view keyColumn,
                                                      DiagnosticList& errors) {
    DiagnosticList cellErrors = checkNumericCells(table);
    errors.insert(errors.end(), cellErrors.begin(), cellErrors.end());
    return readRowKeys(table, *table.findColumn(keyColumn), false, errors);
}

}  // namespace kerf::tables::detail
