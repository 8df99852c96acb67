#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"
#include "core/tables/column_format.h"
#include "core/tables/detail/table_line.h"

namespace kerf::tables {

// One column of a fixed-width table: its name starts at its first character in the header line,
// and it extends to the start of the next name. The last column is open-ended: `width` is the
// widest extent seen in the file, and a cell there may grow past it.
struct TableColumn {
    std::string name;
    size_t start = 0;  // byte offset in the line
    size_t width = 0;  // bytes up to the next column
};

// A HEIDENHAIN TNC table file (TOOL.T, PRESET.PR, *.D, *.PNT, *.TAB, *.CDT ...) kept as its lines.
// Parsing an unmodified file and serializing it gives back the same bytes: line endings, trailing
// spaces, missing final newline, non-UTF-8 bytes and unknown blocks are all kept. An edit rewrites
// only the cell or row it touches.
//
// Rows are addressed by index (0-based, data rows only); diagnostics use 1-based file lines and
// 1-based byte columns. Not thread-safe; copyable value type.
class TncTable {
public:
    // `fileName` is only used in diagnostics. Fails on a missing BEGIN line or column header.
    static Expected<TncTable> parse(std::string_view bytes, std::string fileName = {});

    std::string serialize() const;

    const std::string& fileName() const { return m_fileName; }
    // From the BEGIN line: "TOOL", "T", "MM" (empty when the line names no unit).
    const std::string& tableName() const { return m_tableName; }
    const std::string& extension() const { return m_extension; }
    const std::string& unit() const { return m_unit; }

    const std::vector<TableColumn>& columns() const { return m_columns; }
    std::optional<size_t> findColumn(std::string_view name) const;
    const ColumnFormat& columnFormat(size_t column) const { return m_formats.at(column); }
    // Declares what a column holds; ignored when the table has no such column.
    void setColumnFormat(std::string_view name, ColumnFormat format);

    size_t rowCount() const { return m_rowLines.size(); }
    // Row whose first cell, trimmed, equals `key` / whose first cell is the number `key`.
    std::optional<size_t> findRow(std::string_view key) const;
    std::optional<size_t> findRowByNumber(double key) const;

    // Cell bytes as stored (may be shorter than the column when the line ends early).
    std::string_view rawCell(size_t row, size_t column) const;
    // Cell without surrounding spaces; empty for indexes out of range.
    std::string_view cell(size_t row, size_t column) const;
    // Cell as a number; nothing for empty or non-numeric cells.
    std::optional<double> number(size_t row, size_t column) const;

    // 1-based position of a row / column in the text, for diagnostics.
    uint32_t rowLineNumber(size_t row) const;
    uint32_t headerLineNumber() const { return static_cast<uint32_t>(m_headerLine + 1); }
    uint32_t columnNumber(size_t column) const;

    // Writes `text` left-aligned into the cell, padded with spaces to the column width; text
    // longer than the column is truncated (except in the open-ended last column). Numeric
    // columns accept only numbers (or an empty cell) and refuse numbers that do not leave one
    // space before the next column.
    MaybeError setCell(size_t row, size_t column, std::string_view text);
    // Writes a number as the TNC does: see docs/tables.md, "Number formatting".
    MaybeError setNumber(size_t row, size_t column, double value);
    // Inserts a row before row `index` (== rowCount() appends) with `key` in the first column
    // and each column's default value elsewhere. Returns the new row's index.
    Expected<size_t> insertRow(size_t index, std::string_view key);
    Expected<size_t> appendRow(std::string_view key) { return insertRow(rowCount(), key); }
    MaybeError removeRow(size_t row);
    // Adds a column after the last one, `width` bytes wide (at least its name and a space):
    // the header names it and every row gets an empty cell (rows padded to the full width stay
    // padded). The last column so far gets a fixed width, one space clear of its widest cell.
    MaybeError appendColumn(std::string_view name, size_t width, ColumnFormat format);

    // A diagnostic pointing at a cell / at the header line.
    Diagnostic cellError(size_t row, size_t column, const char* messageTemplate,
                         std::vector<std::string> args) const;
    Diagnostic headerError(const char* messageTemplate, std::vector<std::string> args) const;

private:
    TncTable() = default;

    std::string_view rowText(size_t row) const;
    // The number as it should be written into the cell (row nothing: a new row's cell).
    Expected<std::string> formatForCell(std::optional<size_t> row, size_t column,
                                        double value) const;
    std::string newRowText(std::string_view key) const;
    bool rowsArePadded() const;
    // True if the table has rows and none of them fills the column.
    bool columnIsEmpty(size_t column) const;
    Diagnostic indexError(size_t row, size_t column) const;
    size_t numberWidth(size_t column) const;
    detail::LineEnding defaultEnding() const;
    void indexRows();

    std::string m_fileName;
    std::string m_tableName;
    std::string m_extension;
    std::string m_unit;
    std::vector<detail::TableLine> m_lines;
    size_t m_headerLine = 0;
    std::vector<size_t> m_rowLines;  // index into m_lines of each data row
    std::vector<TableColumn> m_columns;
    std::vector<ColumnFormat> m_formats;  // parallel to m_columns
};

}  // namespace kerf::tables
