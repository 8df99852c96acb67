#include "core/tables/tnc_table.h"

#include <algorithm>
#include <cmath>

#include "core/tables/detail/begin_line.h"
#include "core/tables/detail/description_block.h"
#include "core/tables/detail/number_style_inference.h"
#include "core/tables/tnc_number.h"

namespace kerf::tables {

namespace {

using detail::LineEnding;
using detail::LineKind;
using detail::TableLine;
using detail::trimSpaces;

std::vector<TableColumn> readColumns(std::string_view header) {
    std::vector<TableColumn> columns;
    size_t pos = 0;
    while (true) {
        size_t start = header.find_first_not_of(' ', pos);
        if (start == std::string_view::npos) break;
        size_t end = std::min(header.find(' ', start), header.size());
        if (!columns.empty()) columns.back().width = start - columns.back().start;
        columns.push_back(TableColumn{std::string(header.substr(start, end - start)), start, 0});
        pos = end;
    }
    if (!columns.empty()) columns.back().width = header.size() - columns.back().start;
    return columns;
}

bool isEndLine(std::string_view text) {
    return trimSpaces(text) == "[END]";
}

// Marks the description blocks and blank lines between BEGIN and the column header, collects
// the column formats they declare and returns the index of the line after them.
size_t markPreamble(std::vector<TableLine>& lines,
                    std::vector<detail::DescribedColumn>& described) {
    size_t index = 1;
    while (index < lines.size()) {
        size_t blockLength = detail::descriptionBlockLength(lines, index);
        if (blockLength == 0 && !trimSpaces(lines[index].text).empty()) break;
        if (blockLength > 0) {
            auto columns = detail::readColumnDescriptions(lines, index, blockLength);
            described.insert(described.end(), columns.begin(), columns.end());
        }
        const size_t end = index + std::max<size_t>(blockLength, 1);
        for (; index < end; ++index)
            lines[index].kind = LineKind::Description;
    }
    return index;
}

// Data rows up to "[END]" (blank ones kept aside), then whatever follows it.
void markBody(std::vector<TableLine>& lines, size_t first) {
    bool ended = false;
    for (size_t i = first; i < lines.size(); ++i) {
        if (ended) {
            lines[i].kind = LineKind::Trailer;
        } else if (isEndLine(lines[i].text)) {
            lines[i].kind = LineKind::End;
            ended = true;
        } else {
            lines[i].kind = trimSpaces(lines[i].text).empty() ? LineKind::Blank : LineKind::Row;
        }
    }
}

}  // namespace

Expected<TncTable> TncTable::parse(std::string_view bytes, std::string fileName) {
    TncTable table;
    table.m_fileName = std::move(fileName);
    table.m_lines = detail::splitLines(bytes);
    std::vector<TableLine>& lines = table.m_lines;

    auto begin = detail::parseBeginLine(lines.empty() ? std::string_view() : lines[0].text,
                                        table.m_fileName);
    if (!begin) return begin.error();
    lines[0].kind = LineKind::Begin;
    table.m_tableName = std::move(begin->name);
    table.m_extension = std::move(begin->extension);
    table.m_unit = std::move(begin->unit);

    std::vector<detail::DescribedColumn> described;
    const size_t index = markPreamble(lines, described);
    if (index >= lines.size() || isEndLine(lines[index].text)) {
        return Diagnostic::make(Severity::Error, "table", table.m_fileName,
                                static_cast<uint32_t>(index + 1), 1,
                                KERF_TR_NOOP("the table has no column header line"));
    }
    table.m_headerLine = index;
    lines[index].kind = LineKind::Header;
    table.m_columns = readColumns(lines[index].text);

    markBody(lines, index + 1);
    table.indexRows();

    // The open-ended last column is as wide as the widest row reaches.
    TableColumn& last = table.m_columns.back();
    for (size_t lineIndex : table.m_rowLines) {
        last.width = std::max(last.width, lines[lineIndex].text.size() -
                                              std::min(last.start, lines[lineIndex].text.size()));
    }

    table.m_formats.assign(table.m_columns.size(), ColumnFormat{});
    for (const auto& column : described) {
        table.setColumnFormat(column.name, column.format);
    }
    return table;
}

std::string TncTable::serialize() const {
    std::string out;
    size_t size = 0;
    for (const TableLine& line : m_lines) {
        size += line.text.size() + 2;
    }
    out.reserve(size);
    for (const TableLine& line : m_lines) {
        out += line.text;
        out += detail::endingText(line.ending);
    }
    return out;
}

void TncTable::indexRows() {
    m_rowLines.clear();
    for (size_t i = 0; i < m_lines.size(); ++i) {
        if (m_lines[i].kind == LineKind::Row) m_rowLines.push_back(i);
    }
}

std::optional<size_t> TncTable::findColumn(std::string_view name) const {
    for (size_t i = 0; i < m_columns.size(); ++i) {
        if (m_columns[i].name == name) return i;
    }
    return std::nullopt;
}

void TncTable::setColumnFormat(std::string_view name, ColumnFormat format) {
    if (auto column = findColumn(name)) m_formats[*column] = std::move(format);
}

std::optional<size_t> TncTable::findRow(std::string_view key) const {
    for (size_t row = 0; row < rowCount(); ++row) {
        if (cell(row, 0) == key) return row;
    }
    return std::nullopt;
}

std::optional<size_t> TncTable::findRowByNumber(double key) const {
    for (size_t row = 0; row < rowCount(); ++row) {
        if (number(row, 0) == key) return row;
    }
    return std::nullopt;
}

std::string_view TncTable::rowText(size_t row) const {
    return row < m_rowLines.size() ? std::string_view(m_lines[m_rowLines[row]].text)
                                   : std::string_view();
}

std::string_view TncTable::rawCell(size_t row, size_t column) const {
    if (column >= m_columns.size()) return {};
    std::string_view text = rowText(row);
    const TableColumn& col = m_columns[column];
    if (col.start >= text.size()) return {};
    bool last = column + 1 == m_columns.size();
    return text.substr(col.start, last ? std::string_view::npos : col.width);
}

std::string_view TncTable::cell(size_t row, size_t column) const {
    return trimSpaces(rawCell(row, column));
}

std::optional<double> TncTable::number(size_t row, size_t column) const {
    return parseTncNumber(cell(row, column));
}

uint32_t TncTable::rowLineNumber(size_t row) const {
    return row < m_rowLines.size() ? static_cast<uint32_t>(m_rowLines[row] + 1) : 0;
}

uint32_t TncTable::columnNumber(size_t column) const {
    return column < m_columns.size() ? static_cast<uint32_t>(m_columns[column].start + 1) : 0;
}

Diagnostic TncTable::cellError(size_t row, size_t column, const char* messageTemplate,
                               std::vector<std::string> args) const {
    Diagnostic d = Diagnostic::make(Severity::Error, "table", m_fileName, rowLineNumber(row),
                                    columnNumber(column), messageTemplate);
    d.args = std::move(args);
    return d;
}

Diagnostic TncTable::headerError(const char* messageTemplate, std::vector<std::string> args) const {
    Diagnostic d = Diagnostic::make(Severity::Error, "table", m_fileName, headerLineNumber(), 1,
                                    messageTemplate);
    d.args = std::move(args);
    return d;
}

size_t TncTable::numberWidth(size_t column) const {
    // Numbers keep one space before the next column, as the TNC writes them; text may fill it.
    const size_t width = m_columns[column].width;
    return width > 1 ? width - 1 : width;
}

Diagnostic TncTable::indexError(size_t row, size_t column) const {
    return Diagnostic::make(Severity::Error, "table", m_fileName, 0, 0,
                            KERF_TR_NOOP("the table has no cell at row {1}, column {2}"),
                            std::to_string(row), std::to_string(column));
}

MaybeError TncTable::setCell(size_t row, size_t column, std::string_view text) {
    if (row >= rowCount() || column >= m_columns.size()) return indexError(row, column);
    const TableColumn& col = m_columns[column];
    const bool last = column + 1 == m_columns.size();
    if (text.find_first_of("\r\n") != std::string_view::npos) {
        return cellError(row, column, KERF_TR_NOOP("a cell of column {1} cannot hold a line break"),
                         {col.name});
    }
    std::string content(trimSpaces(text));
    if (m_formats[column].numeric() && !content.empty()) {
        if (!parseTncNumber(content)) {
            return cellError(row, column, KERF_TR_NOOP("column {1} needs a number, not \"{2}\""),
                             {col.name, content});
        }
        if (!last && content.size() > numberWidth(column)) {
            return cellError(row, column,
                             KERF_TR_NOOP("{2} does not fit into column {1} ({3} characters)"),
                             {col.name, content, std::to_string(numberWidth(column))});
        }
    }
    if (!last && content.size() > col.width) content.resize(col.width);
    const size_t contentLength = content.size();
    if (content.size() < col.width) content.append(col.width - content.size(), ' ');

    std::string& line = m_lines[m_rowLines[row]].text;
    const size_t originalLength = line.size();
    if (line.size() < col.start) line.append(col.start - line.size(), ' ');
    size_t oldEnd = last ? line.size() : std::min(line.size(), col.start + col.width);
    line.replace(col.start, oldEnd - col.start, content);
    // A row that ended inside this cell keeps ending right after the text we wrote; the
    // padding of the cells before it stays as it was.
    if (originalLength < col.start + col.width) {
        line.resize(contentLength == 0 ? std::min(originalLength, col.start)
                                       : col.start + contentLength);
    }
    return std::nullopt;
}

Expected<std::string> TncTable::formatForCell(std::optional<size_t> row, size_t column,
                                              double value) const {
    const TableColumn& col = m_columns[column];
    const bool last = column + 1 == m_columns.size();
    NumberStyle style = detail::inferNumberStyle(*this, row, column, value);
    std::string text = formatTncNumber(value, style);
    // Drop trailing zeros the style asked for before giving up, never digits that matter.
    const int needed = minimalDecimals(value, style.decimals);
    while (!last && text.size() > numberWidth(column) && style.decimals > needed) {
        --style.decimals;
        text = formatTncNumber(value, style);
    }
    if (!last && text.size() > numberWidth(column)) {
        const char* message = KERF_TR_NOOP("{2} does not fit into column {1} ({3} characters)");
        std::vector<std::string> args{col.name, text, std::to_string(numberWidth(column))};
        return row ? cellError(*row, column, message, std::move(args))
                   : headerError(message, std::move(args));
    }
    return text;
}

MaybeError TncTable::setNumber(size_t row, size_t column, double value) {
    if (row >= rowCount() || column >= m_columns.size()) return indexError(row, column);
    if (!std::isfinite(value)) {
        return cellError(row, column, KERF_TR_NOOP("column {1} cannot hold an infinite number"),
                         {m_columns[column].name});
    }
    if (m_formats[column].kind == CellKind::Text) {
        return cellError(row, column, KERF_TR_NOOP("column {1} holds text, not numbers"),
                         {m_columns[column].name});
    }
    auto text = formatForCell(row, column, value);
    if (!text) return text.error();
    return setCell(row, column, *text);
}

bool TncTable::rowsArePadded() const {
    // Newer TNCs pad every row to the full width, older ones end a row after its last value.
    const TableColumn& last = m_columns.back();
    size_t reference = m_rowLines.empty() ? m_headerLine : m_rowLines.back();
    return m_lines[reference].text.size() >= last.start + last.width;
}

bool TncTable::columnIsEmpty(size_t column) const {
    if (rowCount() == 0) return false;
    for (size_t row = 0; row < rowCount(); ++row) {
        if (!cell(row, column).empty()) return false;
    }
    return true;
}

std::string TncTable::newRowText(std::string_view key) const {
    std::string line;
    for (size_t column = 0; column < m_columns.size(); ++column) {
        const TableColumn& col = m_columns[column];
        const ColumnFormat& format = m_formats[column];
        std::string content(column == 0 ? key : std::string_view(format.defaultValue));
        // New rows look like the existing ones: a column nobody fills stays empty.
        if (column > 0 && columnIsEmpty(column)) content.clear();
        if (column > 0 && format.numeric()) {
            if (auto value = parseTncNumber(content)) {
                if (auto text = formatForCell(std::nullopt, column, *value)) content = *text;
            }
        }
        if (column + 1 < m_columns.size() && content.size() > col.width) content.resize(col.width);
        line.resize(col.start, ' ');
        line += content;
    }
    const TableColumn& last = m_columns.back();
    if (rowsArePadded()) {
        line.resize(std::max(line.size(), last.start + last.width), ' ');
    } else {
        line.resize(trimSpaces(line).empty() ? 0 : line.find_last_not_of(' ') + 1);
    }
    return line;
}

LineEnding TncTable::defaultEnding() const {
    for (const TableLine& line : m_lines) {
        if (line.ending != LineEnding::None) return line.ending;
    }
    return LineEnding::Lf;
}

Expected<size_t> TncTable::insertRow(size_t index, std::string_view key) {
    if (index > rowCount()) {
        return Diagnostic::make(Severity::Error, "table", m_fileName, 0, 0,
                                KERF_TR_NOOP("cannot insert a row at {1}: the table has {2} rows"),
                                std::to_string(index), std::to_string(rowCount()));
    }
    std::string keyText(trimSpaces(key));
    if (keyText.find_first_of("\r\n") != std::string::npos || keyText.size() > m_columns[0].width) {
        return headerError(KERF_TR_NOOP("\"{2}\" cannot be a key of column {1}"),
                           {m_columns[0].name, keyText});
    }
    size_t position = index < rowCount()   ? m_rowLines[index]
                      : m_rowLines.empty() ? m_headerLine + 1
                                           : m_rowLines.back() + 1;
    TableLine line{newRowText(keyText), defaultEnding(), LineKind::Row};
    if (position == m_lines.size() && m_lines.back().ending == LineEnding::None) {
        // The file had no final newline: the new last line keeps it that way.
        m_lines.back().ending = line.ending;
        line.ending = LineEnding::None;
    }
    m_lines.insert(m_lines.begin() + static_cast<std::ptrdiff_t>(position), std::move(line));
    indexRows();
    return index;
}

MaybeError TncTable::removeRow(size_t row) {
    if (row >= rowCount()) return indexError(row, 0);
    size_t position = m_rowLines[row];
    if (position + 1 == m_lines.size() && m_lines[position].ending == LineEnding::None) {
        m_lines[position - 1].ending = LineEnding::None;
    }
    m_lines.erase(m_lines.begin() + static_cast<std::ptrdiff_t>(position));
    indexRows();
    return std::nullopt;
}

MaybeError TncTable::appendColumn(std::string_view name, size_t width, ColumnFormat format) {
    if (name.empty() || name.find_first_of(" \r\n") != std::string_view::npos || findColumn(name)) {
        return headerError(KERF_TR_NOOP("cannot add a column \"{1}\""), {std::string(name)});
    }
    TableColumn& last = m_columns.back();
    size_t start = last.start + last.width;
    // Keep a space after the widest cell (or name) of the column that was open-ended so far.
    auto reaches = [&](const TableLine& line) {
        return line.text.size() >= start && line.text[start - 1] != ' ';
    };
    bool touching = reaches(m_lines[m_headerLine]);
    for (size_t lineIndex : m_rowLines)
        touching = touching || reaches(m_lines[lineIndex]);
    // Rows padded to the full width end in spaces; a row that ends in its last value is not.
    const bool padded = rowsArePadded() && !touching;
    if (touching) ++start;
    last.width = start - last.start;
    width = std::max(width, name.size() + 1);

    std::string& header = m_lines[m_headerLine].text;
    header.resize(start, ' ');
    header += name;
    if (padded) {
        header.resize(start + width, ' ');
        for (size_t lineIndex : m_rowLines)
            m_lines[lineIndex].text.resize(start + width, ' ');
    }
    m_columns.push_back(TableColumn{std::string(name), start, width});
    m_formats.push_back(std::move(format));
    return std::nullopt;
}

}  // namespace kerf::tables
