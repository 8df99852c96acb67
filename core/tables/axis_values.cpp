#include "core/tables/axis_values.h"

#include "core/tables/tnc_table.h"

namespace kerf::tables {

std::optional<double> AxisValues::get(char axis) const {
    size_t index = kAxisLetters.find(axis);
    return index == std::string_view::npos ? std::nullopt : m_values[index];
}

void AxisValues::set(char axis, std::optional<double> value) {
    size_t index = kAxisLetters.find(axis);
    if (index != std::string_view::npos) m_values[index] = value;
}

AxisValues AxisValues::fromRow(const TncTable& table, size_t row) {
    AxisValues values;
    for (char axis : kAxisLetters) {
        if (auto column = table.findColumn(std::string_view(&axis, 1))) {
            values.set(axis, table.number(row, *column));
        }
    }
    return values;
}

}  // namespace kerf::tables
