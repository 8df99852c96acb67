#pragma once

#include <string_view>
#include <vector>

#include "core/tables/detail/column_spec.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables::detail {

// Width of an axis column in new preset, datum and point tables.
inline constexpr size_t kAxisColumnWidth = 14;

// Appends a signed number column per letter, "+0" in new rows.
void appendAxisColumns(std::vector<ColumnSpec>& specs, std::string_view letters);

// Declares every axis column the table has (X Y Z A B C U V W) as a signed number.
void applyAxisFormats(TncTable& table);

}  // namespace kerf::tables::detail
