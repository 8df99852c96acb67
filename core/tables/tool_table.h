#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/base/expected.h"
#include "core/tables/table_unit.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables {

// One row of TOOL.T. Lengths are in the table's unit (TncTable::unit()); a missing column or an
// empty cell gives the default shown here.
struct ToolData {
    int number = 0;                   // T
    int index = 0;                    // indexed tool: T "5.1" is number 5, index 1
    std::string name;                 // NAME
    double length = 0.0;              // L
    double radius = 0.0;              // R
    double radius2 = 0.0;             // R2
    double deltaLength = 0.0;         // DL
    double deltaRadius = 0.0;         // DR
    double deltaRadius2 = 0.0;        // DR2
    bool locked = false;              // TL: "L" (or "1") locks the tool
    int cutterCount = 0;              // CUT
    double plungeAngle = 0.0;         // ANGLE, degrees
    double cuttingLength = 0.0;       // LCUTS
    double pointAngle = 0.0;          // T-ANGLE, degrees
    double pitch = 0.0;               // PITCH
    double maxTime1Minutes = 0.0;     // TIME1
    double maxTime2Minutes = 0.0;     // TIME2
    double currentTimeMinutes = 0.0;  // CUR_TIME (older files: CUR.TIME)
    std::string replacementTool;      // RT, as written
    std::string comment;              // DOC
    size_t row = 0;                   // row in table()
};

// Typed view of a tool table (.T). Validates on load: key column T present, tool numbers whole,
// >= 0 and unique, numeric columns numeric, TL empty, 0, 1 or L.
class ToolTable {
public:
    static Expected<ToolTable> fromTable(TncTable table);
    static Expected<ToolTable> parse(std::string_view bytes, std::string fileName = {});
    static Expected<ToolTable> load(const std::filesystem::path& path);
    MaybeError save(const std::filesystem::path& path) const;
    std::string serialize() const { return m_table.serialize(); }

    // A TNC 320 TOOL.T with the standard column set and the null tool 0.
    static std::string createDefault(TableUnit unit = TableUnit::Millimetre);

    const TncTable& table() const { return m_table; }
    const std::vector<ToolData>& tools() const { return m_tools; }

    const ToolData* byNumber(int number, int index = 0) const;
    // Names match case-sensitively. Of several tools with the name, the first one not locked;
    // if all are locked, the first one (so the caller can report "tool locked").
    const ToolData* byName(std::string_view name) const;
    // Any numeric column of a tool, e.g. for cycles reading columns ToolData lacks. Nothing if
    // the tool or column is missing or the cell is empty or not a number. `index`: the row of
    // an indexed tool (T 5.2).
    std::optional<double> numberCell(int tool, std::string_view column, int index = 0) const;

    // Edits; each leaves the table unchanged and returns the reason if it fails.
    MaybeError setNumber(int tool, std::string_view column, double value, int index = 0);
    MaybeError setText(int tool, std::string_view column, std::string_view text, int index = 0);
    // Adds a row in ascending order with default cells.
    MaybeError addTool(int number);
    MaybeError removeTool(int number);

private:
    explicit ToolTable(TncTable table) : m_table(std::move(table)) {}
    // Row and column of a tool's cell, or why there is none.
    Expected<std::pair<size_t, size_t>> cellOf(int tool, int index, std::string_view column) const;

    TncTable m_table;
    std::vector<ToolData> m_tools;
};

}  // namespace kerf::tables
