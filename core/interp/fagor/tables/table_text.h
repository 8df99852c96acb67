#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"

namespace kerf::fagor {

// One field of a table line: upper-case letters and a number, "X12.5", "F3", "G54".
struct TableField {
    std::string name;
    double value = 0.0;
    size_t offset = 0;  // byte offset of the field in its line
    size_t length = 0;  // bytes of the field
};

// A data line: a key word ("D1", "G54", "G159N7", "PLC", "ACTIVE") and its fields.
struct TableRow {
    std::string key;
    std::vector<TableField> fields;
    size_t line = 0;  // 0-based line in the file

    const TableField* field(std::string_view name) const;
};

// The text of a Kerf FAGOR table file (docs/fagor.md, "Tables"), kept as its lines so that an
// unmodified table serializes to the same bytes and an edit rewrites only the field it touches:
//
//   %TOOL OFFSETS,MX,          optional transfer header, as the control sends tables
//   ; comment                  comment lines and blank lines are kept
//   D1 X12.5 Z-30 F3 R0.8      key word, then fields separated by blanks; ';' starts a comment
class TableText {
public:
    // `fileName` is only used in diagnostics (code "table", 1-based line and byte column).
    static Expected<TableText> parse(std::string_view bytes, std::string fileName = {});
    // An empty table with a header line and a comment line.
    static TableText create(std::string_view header, std::string_view comment);

    std::string serialize() const;

    const std::string& fileName() const { return m_fileName; }
    const std::vector<TableRow>& rows() const { return m_rows; }
    const TableRow* row(std::string_view key) const;

    // Sets a field of a row: rewrites it in place, or appends it to the row; appends the row when
    // there is none. Values are written with at most `decimals` decimals, trailing zeros dropped.
    void set(std::string_view key, std::string_view name, double value, int decimals = 4);
    // Replaces a row's fields (used for rows whose fields repeat names, such as ACTIVE).
    void replaceRow(std::string_view key, std::string_view fields);
    // Removes the row's line, with any comment on it; false when there is no such row.
    bool removeRow(std::string_view key);

    Diagnostic error(size_t line, size_t column, const char* messageTemplate,
                     std::vector<std::string> args = {}) const;

private:
    struct Line {
        std::string text;
        std::string ending;  // "\n", "\r\n", "\r" or "" for a last line without one
    };
    MaybeError parseLine(size_t index);
    void appendLine(std::string text);

    std::string m_fileName;
    std::vector<Line> m_lines;
    std::vector<TableRow> m_rows;
};

// A number as tables and WRITE blocks show it: at most `decimals` decimals, trailing zeros and a
// trailing point dropped, never "-0" ("10", "-0.25", "3.1416").
std::string formatTableNumber(double value, int decimals = 4);

}  // namespace kerf::fagor
