#include "core/tables/detail/column_spec.h"

namespace kerf::tables::detail {

namespace {

void appendPadded(std::string& line, std::string_view text, size_t width) {
    line += text;
    if (text.size() < width) line.append(width - text.size(), ' ');
}

ColumnSpec makeSpec(std::string name, size_t width, CellKind kind, bool explicitSign,
                    std::string defaultValue) {
    ColumnSpec spec;
    spec.name = std::move(name);
    spec.width = width;
    spec.format.kind = kind;
    spec.format.explicitSign = explicitSign;
    spec.format.defaultValue = std::move(defaultValue);
    return spec;
}

}  // namespace

std::string buildTableText(std::string_view name, std::string_view extension, TableUnit unit,
                           const std::vector<ColumnSpec>& columns,
                           const std::vector<std::vector<std::string>>& rows) {
    std::string text = "BEGIN ";
    text += name;
    text += '.';
    text += extension;
    text += ' ';
    text += unitKeyword(unit);
    text += '\n';
    for (const ColumnSpec& column : columns)
        appendPadded(text, column.name, column.width);
    text += '\n';
    for (const auto& row : rows) {
        for (size_t i = 0; i < columns.size(); ++i) {
            appendPadded(text, i < row.size() ? row[i] : columns[i].format.defaultValue,
                         columns[i].width);
        }
        text += '\n';
    }
    text += "[END]\n";
    return text;
}

void applyColumnSpecs(TncTable& table, const std::vector<ColumnSpec>& columns) {
    for (const ColumnSpec& column : columns)
        table.setColumnFormat(column.name, column.format);
}

ColumnSpec textColumn(std::string name, size_t width, std::string defaultValue) {
    return makeSpec(std::move(name), width, CellKind::Text, false, std::move(defaultValue));
}

ColumnSpec numberColumn(std::string name, size_t width, bool explicitSign,
                        std::string defaultValue) {
    return makeSpec(std::move(name), width, CellKind::Number, explicitSign,
                    std::move(defaultValue));
}

ColumnSpec integerColumn(std::string name, size_t width, std::string defaultValue) {
    return makeSpec(std::move(name), width, CellKind::Integer, false, std::move(defaultValue));
}

ColumnSpec otherColumn(std::string name, size_t width, std::string defaultValue) {
    return makeSpec(std::move(name), width, CellKind::Unknown, false, std::move(defaultValue));
}

}  // namespace kerf::tables::detail
