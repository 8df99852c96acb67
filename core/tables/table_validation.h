#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/base/expected.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables {

// Checks shared by the typed tables. Each diagnostic names the file, the 1-based line and the
// 1-based column where the offending cell starts.

// Every cell of a Number or Integer column is empty or a (whole) number.
DiagnosticList checkNumericCells(const TncTable& table);

// The column exists; the error points at the column header line.
MaybeError requireColumn(const TncTable& table, std::string_view name);

// Key of a row: tool 5 is {5, 0}, the indexed tool "5.1" is {5, 1}.
struct RowKey {
    int number = 0;
    int index = 0;

    friend bool operator==(const RowKey&, const RowKey&) = default;
};

// Reads the key column: each row needs a whole number >= 0 (or "number.index" with
// allowIndex), and no key may appear twice. Rows with a bad key get nothing; the problems are
// appended to `errors`.
std::vector<std::optional<RowKey>> readRowKeys(const TncTable& table, size_t keyColumn,
                                               bool allowIndex, DiagnosticList& errors);

// Row where a new key goes so that the keys stay ascending.
size_t sortedInsertPosition(const std::vector<std::optional<RowKey>>& keys, RowKey key);

}  // namespace kerf::tables
