#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/tables/column_format.h"
#include "core/tables/table_unit.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables::detail {

// A column a typed table knows: its name, the width a new file gives it and what it holds.
struct ColumnSpec {
    std::string name;
    size_t width = 0;
    ColumnFormat format;
};

// Text of a new table: "BEGIN <name>.<extension> <unit>", the padded column header, one padded
// row per entry of `rows` (cells in column order; a missing cell takes the column's default
// value) and "[END]", all with LF endings as the TNC writes them.
std::string buildTableText(std::string_view name, std::string_view extension, TableUnit unit,
                           const std::vector<ColumnSpec>& columns,
                           const std::vector<std::vector<std::string>>& rows);

// Declares each known column's format on a parsed table.
void applyColumnSpecs(TncTable& table, const std::vector<ColumnSpec>& columns);

// Shorthands for the spec tables.
ColumnSpec textColumn(std::string name, size_t width, std::string defaultValue = {});
ColumnSpec numberColumn(std::string name, size_t width, bool explicitSign,
                        std::string defaultValue = {});
ColumnSpec integerColumn(std::string name, size_t width, std::string defaultValue = {});
ColumnSpec otherColumn(std::string name, size_t width, std::string defaultValue = {});

}  // namespace kerf::tables::detail
