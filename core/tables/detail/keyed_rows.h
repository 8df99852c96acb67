#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"
#include "core/tables/table_validation.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables::detail {

// Helpers for the tables keyed by a whole number (tools, presets, datums, points).

// The row whose key is `number`; the message template says what is missing ("preset {1} ...").
Expected<size_t> rowOfKey(const std::vector<std::optional<RowKey>>& keys, const TncTable& table,
                          int number, const char* messageTemplate);

// Writes an axis value, or empties the cell for no value.
MaybeError setAxisCell(TncTable& table, size_t row, char axis, std::optional<double> value);

// Inserts a row with key `number` where the keys stay ascending.
MaybeError insertKeyedRow(TncTable& table, size_t keyColumn,
                          const std::vector<std::optional<RowKey>>& keys, int number);

// Validates a table whose column `keyColumn` exists (see requireColumn) and whose column formats
// are declared: keys whole, >= 0 and unique, numeric columns numeric. Appends to `errors`.
std::vector<std::optional<RowKey>> validateKeyedTable(const TncTable& table,
                                                      std::string_view keyColumn,
                                                      DiagnosticList& errors);

}  // namespace kerf::tables::detail
