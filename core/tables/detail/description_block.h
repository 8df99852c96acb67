#pragma once

#include <string>
#include <vector>

#include "core/tables/column_format.h"
#include "core/tables/detail/table_line.h"

namespace kerf::tables::detail {

// Some tables describe their columns before the column header: .CDT files in a
// "#STRUCTBEGIN" ... "#STRUCTEND" section, configurable tables such as palletmag.tab in a
// "TableDescription (" ... ")" block. The lines stay opaque; we only borrow the column types.

// How many lines the block starting at lines[first] spans; 0 if none starts there. A block that
// never ends runs to the end of the file.
size_t descriptionBlockLength(const std::vector<TableLine>& lines, size_t first);

struct DescribedColumn {
    std::string name;
    ColumnFormat format;
};

// The columns declared in lines[first, first + count).
std::vector<DescribedColumn> readColumnDescriptions(const std::vector<TableLine>& lines,
                                                    size_t first, size_t count);

}  // namespace kerf::tables::detail
