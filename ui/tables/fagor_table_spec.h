#pragma once

#include <QString>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"
#include "core/interp/fagor/tables/table_text.h"
#include "ui/tables/table_kinds.h"

namespace kerf::ui {

// One editable field of a FAGOR table row ("X" of "D3 X12.5 Z-30").
struct FagorColumn {
    std::string field;
    QString unit;
    bool integer = false;
    double minimum = -99999.9999;
    double maximum = 99999.9999;
};

// How the table editor shows a FAGOR table: which rows, which fields, and the typed table's own
// check of the whole text (ToolOffsetTable::parse ...).
struct FagorTableSpec {
    // Rows keyed "<prefix><n>", firstKey <= n <= lastKey, added and removed by the operator;
    // empty when the rows are fixed.
    std::string keyPrefix;
    int firstKey = 1;
    int lastKey = 255;
    // Fixed rows (every zero offset exists): shown whether or not the file has them.
    std::vector<std::string> fixedKeys;
    std::vector<FagorColumn> columns;
    std::function<MaybeError(const fagor::TableText&)> validate;
};

// The spec of a FAGOR kind; `axisLetters` are the zero-offset columns (the machine's axes).
FagorTableSpec fagorTableSpec(TableKind kind, std::string_view axisLetters);

}  // namespace kerf::ui
