#pragma once

#include <cstdint>
#include <string>

namespace kerf::tables {

// Unknown: nobody declared the column; it may hold text or numbers.
enum class CellKind : uint8_t { Unknown, Text, Number, Integer };

// What a column holds, as far as we know it: from a typed view (ToolTable knows that L is a signed
// length) or from the table's own description block (.CDT, palletmag.tab). Columns nobody
// describes are Unknown: their cells are readable as text and as numbers.
struct ColumnFormat {
    CellKind kind = CellKind::Unknown;
    // Style for a column that holds no number yet; existing cells always win.
    bool explicitSign = false;
    int defaultDecimals = 0;
    // Content of this column in a new row: a number is written in the column's style.
    std::string defaultValue;

    bool numeric() const { return kind == CellKind::Number || kind == CellKind::Integer; }
};

}  // namespace kerf::tables
