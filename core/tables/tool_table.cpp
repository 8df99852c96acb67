#include "core/tables/tool_table.h"

#include <cmath>

#include "core/tables/detail/column_spec.h"
#include "core/tables/detail/keyed_rows.h"
#include "core/tables/detail/tool_columns.h"
#include "core/tables/detail/typed_table.h"
#include "core/tables/table_validation.h"

namespace kerf::tables {

namespace {

double numberOr(const TncTable& table, size_t row, std::optional<size_t> column,
                double fallback = 0.0) {
    if (!column) return fallback;
    return table.number(row, *column).value_or(fallback);
}

std::string textOr(const TncTable& table, size_t row, std::optional<size_t> column) {
    return column ? std::string(table.cell(row, *column)) : std::string();
}

// Column positions looked up once per table.
struct ToolColumns {
    std::optional<size_t> name, length, radius, radius2, deltaLength, deltaRadius, deltaRadius2,
        locked, cutterCount, plungeAngle, cuttingLength, pointAngle, pitch, time1, time2,
        currentTime, replacement, comment, probeNumber;

    explicit ToolColumns(const TncTable& table)
        : name(table.findColumn("NAME")),
          length(table.findColumn("L")),
          radius(table.findColumn("R")),
          radius2(table.findColumn("R2")),
          deltaLength(table.findColumn("DL")),
          deltaRadius(table.findColumn("DR")),
          deltaRadius2(table.findColumn("DR2")),
          locked(table.findColumn("TL")),
          cutterCount(table.findColumn("CUT")),
          plungeAngle(table.findColumn("ANGLE")),
          cuttingLength(table.findColumn("LCUTS")),
          pointAngle(table.findColumn("T-ANGLE")),
          pitch(table.findColumn("PITCH")),
          time1(table.findColumn("TIME1")),
          time2(table.findColumn("TIME2")),
          currentTime(table.findColumn("CUR_TIME")),
          replacement(table.findColumn("RT")),
          comment(table.findColumn("DOC")),
          probeNumber(table.findColumn("TP_NO")) {
        if (!currentTime) currentTime = table.findColumn("CUR.TIME");
    }
};

// A whole number within [0, max] in `column` (checked before it is converted to int: a value
// beyond int is undefined behaviour), or an error at the cell. Empty cells are fine.
void checkWholeNumbers(const TncTable& table, std::optional<size_t> column, double max,
                       DiagnosticList& errors) {
    if (!column) return;
    for (size_t row = 0; row < table.rowCount(); ++row) {
        const std::string_view text = table.cell(row, *column);
        if (text.empty()) continue;
        const std::optional<double> value = table.number(row, *column);
        if (value && *value >= 0.0 && *value <= max && std::floor(*value) == *value) continue;
        errors.push_back(table.cellError(
            row, *column,
            KERF_TR_NOOP("column {1} needs a whole number from 0 to {2}, not \"{3}\""),
            {table.columns()[*column].name, std::to_string(static_cast<int>(max)),
             std::string(text)}));
    }
}

// TL: empty or "0" free, "L" or "1" locked; anything else is reported.
std::optional<bool> parseLock(std::string_view text) {
    if (text.empty() || text == "0") return false;
    if (text == "L" || text == "1") return true;
    return std::nullopt;
}

ToolData readTool(const TncTable& table, const ToolColumns& c, size_t row, RowKey key) {
    ToolData tool;
    tool.number = key.number;
    tool.index = key.index;
    tool.row = row;
    tool.name = textOr(table, row, c.name);
    tool.length = numberOr(table, row, c.length);
    tool.radius = numberOr(table, row, c.radius);
    tool.radius2 = numberOr(table, row, c.radius2);
    tool.deltaLength = numberOr(table, row, c.deltaLength);
    tool.deltaRadius = numberOr(table, row, c.deltaRadius);
    tool.deltaRadius2 = numberOr(table, row, c.deltaRadius2);
    tool.locked = c.locked && parseLock(table.cell(row, *c.locked)).value_or(false);
    tool.cutterCount = static_cast<int>(numberOr(table, row, c.cutterCount));
    tool.plungeAngle = numberOr(table, row, c.plungeAngle);
    tool.cuttingLength = numberOr(table, row, c.cuttingLength);
    tool.pointAngle = numberOr(table, row, c.pointAngle);
    tool.pitch = numberOr(table, row, c.pitch);
    tool.maxTime1Minutes = numberOr(table, row, c.time1);
    tool.maxTime2Minutes = numberOr(table, row, c.time2);
    tool.currentTimeMinutes = numberOr(table, row, c.currentTime);
    tool.replacementTool = textOr(table, row, c.replacement);
    tool.comment = textOr(table, row, c.comment);
    return tool;
}

}  // namespace

Expected<ToolTable> ToolTable::fromTable(TncTable table) {
    if (MaybeError missing = requireColumn(table, "T")) return *missing;
    detail::applyColumnSpecs(table, detail::toolColumns());
    DiagnosticList errors = checkNumericCells(table);
    auto keys = readRowKeys(table, *table.findColumn("T"), true, errors);
    ToolColumns columns(table);
    // CUT: the TNC allows 99 teeth; TP_NO: a row of the touch-probe table.
    checkWholeNumbers(table, columns.cutterCount, 99.0, errors);
    checkWholeNumbers(table, columns.probeNumber, 99999.0, errors);
    if (columns.locked) {
        for (size_t row = 0; row < table.rowCount(); ++row) {
            std::string_view text = table.cell(row, *columns.locked);
            if (!parseLock(text)) {
                errors.push_back(table.cellError(
                    row, *columns.locked,
                    KERF_TR_NOOP("column {1} needs L, 1, 0 or nothing, not \"{2}\""),
                    {"TL", std::string(text)}));
            }
        }
    }
    if (!errors.empty()) return errors.front();

    ToolTable result(std::move(table));
    for (size_t row = 0; row < keys.size(); ++row) {
        result.m_tools.push_back(readTool(result.m_table, columns, row, *keys[row]));
    }
    return result;
}

Expected<ToolTable> ToolTable::parse(std::string_view bytes, std::string fileName) {
    return detail::parseTyped<ToolTable>(bytes, std::move(fileName));
}

Expected<ToolTable> ToolTable::load(const std::filesystem::path& path) {
    return detail::loadTyped<ToolTable>(path);
}

MaybeError ToolTable::save(const std::filesystem::path& path) const {
    return saveTable(m_table, path);
}

std::string ToolTable::createDefault(TableUnit unit) {
    return detail::buildTableText("TOOL", "T", unit, detail::toolColumns(), {{"0"}});
}

const ToolData* ToolTable::byNumber(int number, int index) const {
    for (const ToolData& tool : m_tools) {
        if (tool.number == number && tool.index == index) return &tool;
    }
    return nullptr;
}

const ToolData* ToolTable::byName(std::string_view name) const {
    if (name.empty()) return nullptr;
    const ToolData* firstMatch = nullptr;
    for (const ToolData& tool : m_tools) {
        if (tool.name != name) continue;
        if (!tool.locked) return &tool;
        if (!firstMatch) firstMatch = &tool;
    }
    return firstMatch;
}

std::optional<double> ToolTable::numberCell(int tool, std::string_view column, int index) const {
    auto cell = cellOf(tool, index, column);
    if (!cell) return std::nullopt;
    return m_table.number(cell->first, cell->second);
}

Expected<std::pair<size_t, size_t>> ToolTable::cellOf(int tool, int index,
                                                      std::string_view column) const {
    const ToolData* data = byNumber(tool, index);
    if (!data) {
        const std::string name =
            index == 0 ? std::to_string(tool) : std::to_string(tool) + "." + std::to_string(index);
        return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                                KERF_TR_NOOP("tool {1} is not in the tool table"), name);
    }
    auto found = m_table.findColumn(column);
    if (!found) {
        return m_table.headerError(KERF_TR_NOOP("the table has no column {1}"),
                                   {std::string(column)});
    }
    return std::make_pair(data->row, *found);
}

MaybeError ToolTable::setNumber(int tool, std::string_view column, double value, int index) {
    auto cell = cellOf(tool, index, column);
    if (!cell) return cell.error();
    return detail::editTyped(
        *this, [&](TncTable& table) { return table.setNumber(cell->first, cell->second, value); });
}

MaybeError ToolTable::setText(int tool, std::string_view column, std::string_view text, int index) {
    auto cell = cellOf(tool, index, column);
    if (!cell) return cell.error();
    return detail::editTyped(
        *this, [&](TncTable& table) { return table.setCell(cell->first, cell->second, text); });
}

MaybeError ToolTable::addTool(int number) {
    if (byNumber(number)) {
        return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                                KERF_TR_NOOP("tool {1} is already in the tool table"),
                                std::to_string(number));
    }
    std::vector<std::optional<RowKey>> keys;
    for (const ToolData& tool : m_tools)
        keys.push_back(RowKey{tool.number, tool.index});
    return detail::editTyped(*this, [&](TncTable& table) {
        return detail::insertKeyedRow(table, *table.findColumn("T"), keys, number);
    });
}

MaybeError ToolTable::removeTool(int number) {
    const ToolData* tool = byNumber(number);
    if (!tool) {
        return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                                KERF_TR_NOOP("tool {1} is not in the tool table"),
                                std::to_string(number));
    }
    size_t row = tool->row;
    return detail::editTyped(*this, [&](TncTable& table) { return table.removeRow(row); });
}

}  // namespace kerf::tables
