#include "core/tables/point_table.h"

#include "core/tables/detail/axis_columns.h"
#include "core/tables/detail/keyed_rows.h"
#include "core/tables/detail/typed_table.h"

namespace kerf::tables {

namespace {

constexpr std::string_view kKey = "NR";
constexpr const char* kMissing = KERF_TR_NOOP("point {1} is not in the point table");

const std::vector<detail::ColumnSpec>& pointColumns() {
    static const std::vector<detail::ColumnSpec> columns = [] {
        std::vector<detail::ColumnSpec> specs = {detail::otherColumn("NR", 8)};
        detail::appendAxisColumns(specs, "XYZ");
        specs.push_back(detail::textColumn("FADE", 5));
        specs.push_back(detail::textColumn("CLEAR", 6));
        return specs;
    }();
    return columns;
}

std::optional<bool> parseFlag(std::string_view text) {
    if (text.empty() || text == "N" || text == "0") return false;
    if (text == "Y" || text == "1") return true;
    return std::nullopt;
}

// Reads a flag column of every row; bad values go to `errors`.
std::vector<bool> readFlags(const TncTable& table, std::string_view name, DiagnosticList& errors) {
    std::vector<bool> flags(table.rowCount(), false);
    auto column = table.findColumn(name);
    if (!column) return flags;
    for (size_t row = 0; row < table.rowCount(); ++row) {
        std::string_view text = table.cell(row, *column);
        auto flag = parseFlag(text);
        if (!flag) {
            errors.push_back(table.cellError(
                row, *column, KERF_TR_NOOP("column {1} needs Y or nothing, not \"{2}\""),
                {std::string(name), std::string(text)}));
        }
        flags[row] = flag.value_or(false);
    }
    return flags;
}

}  // namespace

Expected<PointTable> PointTable::fromTable(TncTable table) {
    if (MaybeError missing = requireColumn(table, kKey)) return *missing;
    detail::applyColumnSpecs(table, pointColumns());
    detail::applyAxisFormats(table);
    DiagnosticList errors;
    auto keys = detail::validateKeyedTable(table, kKey, errors);
    std::vector<bool> fades = readFlags(table, "FADE", errors);
    std::vector<bool> clears = readFlags(table, "CLEAR", errors);
    if (!errors.empty()) return errors.front();

    PointTable result(std::move(table));
    for (size_t row = 0; row < keys.size(); ++row) {
        PointData point;
        point.number = keys[row]->number;
        point.axes = AxisValues::fromRow(result.m_table, row);
        point.fade = fades[row];
        point.clear = clears[row];
        point.row = row;
        result.m_points.push_back(std::move(point));
    }
    result.m_keys = std::move(keys);
    return result;
}

Expected<PointTable> PointTable::parse(std::string_view bytes, std::string fileName) {
    return detail::parseTyped<PointTable>(bytes, std::move(fileName));
}

Expected<PointTable> PointTable::load(const std::filesystem::path& path) {
    return detail::loadTyped<PointTable>(path);
}

MaybeError PointTable::save(const std::filesystem::path& path) const {
    return saveTable(m_table, path);
}

std::string PointTable::createDefault(std::string_view name, TableUnit unit) {
    return detail::buildTableText(name, "PNT", unit, pointColumns(), {});
}

const PointData* PointTable::byNumber(int number) const {
    for (const PointData& point : m_points) {
        if (point.number == number) return &point;
    }
    return nullptr;
}

MaybeError PointTable::setAxis(int number, char axis, std::optional<double> value) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    return detail::editTyped(
        *this, [&](TncTable& table) { return detail::setAxisCell(table, *row, axis, value); });
}

MaybeError PointTable::setFlag(int number, std::string_view column, bool value) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    auto index = m_table.findColumn(column);
    if (!index) {
        return m_table.headerError(KERF_TR_NOOP("the table has no column {1}"),
                                   {std::string(column)});
    }
    return detail::editTyped(
        *this, [&](TncTable& table) { return table.setCell(*row, *index, value ? "Y" : ""); });
}

MaybeError PointTable::setFade(int number, bool fade) {
    return setFlag(number, "FADE", fade);
}

MaybeError PointTable::setClear(int number, bool clear) {
    return setFlag(number, "CLEAR", clear);
}

MaybeError PointTable::addPoint(int number) {
    if (byNumber(number)) {
        return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                                KERF_TR_NOOP("point {1} is already in the point table"),
                                std::to_string(number));
    }
    return detail::editTyped(*this, [&](TncTable& table) {
        return detail::insertKeyedRow(table, *table.findColumn(kKey), m_keys, number);
    });
}

MaybeError PointTable::removePoint(int number) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    return detail::editTyped(*this, [&](TncTable& table) { return table.removeRow(*row); });
}

}  // namespace kerf::tables
