#include "core/tables/free_table.h"

#include "core/tables/detail/table_line.h"
#include "core/tables/table_file.h"
#include "core/tables/tnc_number.h"

namespace kerf::tables {

Expected<FreeTable> FreeTable::open(const std::filesystem::path& path) {
    auto table = loadTable(path);
    if (!table) return table.error();
    return FreeTable(std::move(*table), path);
}

Expected<FreeTable> FreeTable::fromTable(TncTable table, std::filesystem::path path) {
    return FreeTable(std::move(table), std::move(path));
}

Expected<size_t> FreeTable::findRow(int64_t row) const {
    if (auto index = m_table.findRowByNumber(static_cast<double>(row))) return *index;
    return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                            KERF_TR_NOOP("the table has no row {1}"), std::to_string(row));
}

Expected<std::vector<size_t>> FreeTable::findColumns(std::string_view columnList) const {
    std::vector<size_t> columns;
    size_t pos = 0;
    while (true) {
        size_t comma = columnList.find(',', pos);
        std::string_view name = detail::trimSpaces(columnList.substr(pos, comma - pos));
        auto column = m_table.findColumn(name);
        if (!column) {
            return m_table.headerError(KERF_TR_NOOP("the table has no column \"{1}\""),
                                       {std::string(name)});
        }
        columns.push_back(*column);
        if (comma == std::string_view::npos) break;
        pos = comma + 1;
    }
    return columns;
}

Expected<std::vector<double>> FreeTable::read(int64_t row, std::string_view columnList) const {
    auto index = findRow(row);
    if (!index) return index.error();
    auto columns = findColumns(columnList);
    if (!columns) return columns.error();
    std::vector<double> values;
    for (size_t column : *columns) {
        const std::string& name = m_table.columns()[column].name;
        std::string_view text = m_table.cell(*index, column);
        if (text.empty()) {
            return m_table.cellError(*index, column, KERF_TR_NOOP("cell {1} of row {2} is empty"),
                                     {name, std::to_string(row)});
        }
        auto value = parseTncNumber(text);
        if (!value) {
            return m_table.cellError(*index, column,
                                     KERF_TR_NOOP("column {1} needs a number, not \"{2}\""),
                                     {name, std::string(text)});
        }
        values.push_back(*value);
    }
    return values;
}

MaybeError FreeTable::write(int64_t row, std::string_view columnList,
                            std::span<const double> values) {
    auto index = findRow(row);
    if (!index) return index.error();
    auto columns = findColumns(columnList);
    if (!columns) return columns.error();
    if (columns->size() != values.size()) {
        return m_table.headerError(
            KERF_TR_NOOP("{1} columns named but {2} values given"),
            {std::to_string(columns->size()), std::to_string(values.size())});
    }
    // Write into a copy so that a failure in the third column leaves the first two untouched.
    TncTable copy = m_table;
    for (size_t i = 0; i < values.size(); ++i) {
        size_t column = (*columns)[i];
        std::string_view text = copy.cell(*index, column);
        if (!text.empty() && !parseTncNumber(text)) {
            return copy.cellError(*index, column,
                                  KERF_TR_NOOP("column {1} holds text, not numbers"),
                                  {copy.columns()[column].name});
        }
        if (MaybeError error = copy.setNumber(*index, column, values[i])) return error;
    }
    m_table = std::move(copy);
    m_modified = true;
    return std::nullopt;
}

MaybeError FreeTable::save() const {
    return saveTable(m_table, m_path);
}

}  // namespace kerf::tables
