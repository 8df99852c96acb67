#pragma once

#include <vector>

#include "core/tables/detail/column_spec.h"

namespace kerf::tables::detail {

// The TNC 320 TOOL.T columns in their usual order, with widths as the control writes them.
const std::vector<ColumnSpec>& toolColumns();

}  // namespace kerf::tables::detail
