#include "core/tables/detail/axis_columns.h"

#include "core/tables/axis_values.h"

namespace kerf::tables::detail {

void appendAxisColumns(std::vector<ColumnSpec>& specs, std::string_view letters) {
    for (char axis : letters) {
        specs.push_back(numberColumn(std::string(1, axis), kAxisColumnWidth, true, "+0"));
    }
}

void applyAxisFormats(TncTable& table) {
    std::vector<ColumnSpec> specs;
    appendAxisColumns(specs, kAxisLetters);
    applyColumnSpecs(table, specs);
}

}  // namespace kerf::tables::detail
