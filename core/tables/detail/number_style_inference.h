#pragma once

#include <cstddef>
#include <optional>

#include "core/tables/tnc_number.h"

namespace kerf::tables {
class TncTable;
}

namespace kerf::tables::detail {

// The style in which the TNC would write `value` into a cell: the sign convention, separator and
// decimals of the cell's current number, else those most used in its column (then in the whole
// table for the separator), else the column's declared defaults. Decimals grow when the value
// needs more (up to kMaxDecimals); integer columns get none.
NumberStyle inferNumberStyle(const TncTable& table, std::optional<size_t> row, size_t column,
                             double value);

inline constexpr int kMaxDecimals = 5;

}  // namespace kerf::tables::detail
