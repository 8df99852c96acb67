#include "core/tables/datum_table.h"

#include "core/tables/detail/axis_columns.h"
#include "core/tables/detail/keyed_rows.h"
#include "core/tables/detail/typed_table.h"

namespace kerf::tables {

namespace {

constexpr const char* kMissing = KERF_TR_NOOP("datum {1} is not in the datum table");

const std::vector<detail::ColumnSpec>& datumColumns() {
    static const std::vector<detail::ColumnSpec> columns = [] {
        std::vector<detail::ColumnSpec> specs = {detail::otherColumn("D", 8)};
        detail::appendAxisColumns(specs, "XYZABC");
        specs.push_back(detail::textColumn("DOC", 17));
        return specs;
    }();
    return columns;
}

}  // namespace

Expected<DatumTable> DatumTable::fromTable(TncTable table) {
    // The TNC calls the key column D; some tables and manuals use NR.
    std::string keyColumn = table.findColumn("D") || !table.findColumn("NR") ? "D" : "NR";
    if (MaybeError missing = requireColumn(table, keyColumn)) return *missing;
    detail::applyColumnSpecs(table, datumColumns());
    detail::applyAxisFormats(table);
    DiagnosticList errors;
    auto keys = detail::validateKeyedTable(table, keyColumn, errors);
    if (!errors.empty()) return errors.front();

    DatumTable result(std::move(table));
    const TncTable& t = result.m_table;
    auto doc = t.findColumn("DOC");
    for (size_t row = 0; row < keys.size(); ++row) {
        DatumData datum;
        datum.number = keys[row]->number;
        datum.comment = doc ? std::string(t.cell(row, *doc)) : std::string();
        datum.axes = AxisValues::fromRow(t, row);
        datum.row = row;
        result.m_datums.push_back(std::move(datum));
    }
    result.m_keys = std::move(keys);
    result.m_keyColumn = std::move(keyColumn);
    return result;
}

Expected<DatumTable> DatumTable::parse(std::string_view bytes, std::string fileName) {
    return detail::parseTyped<DatumTable>(bytes, std::move(fileName));
}

Expected<DatumTable> DatumTable::load(const std::filesystem::path& path) {
    return detail::loadTyped<DatumTable>(path);
}

MaybeError DatumTable::save(const std::filesystem::path& path) const {
    return saveTable(m_table, path);
}

std::string DatumTable::createDefault(std::string_view name, TableUnit unit) {
    return detail::buildTableText(name, "D", unit, datumColumns(), {{"0"}});
}

const DatumData* DatumTable::byNumber(int number) const {
    for (const DatumData& datum : m_datums) {
        if (datum.number == number) return &datum;
    }
    return nullptr;
}

MaybeError DatumTable::setAxis(int number, char axis, std::optional<double> value) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    return detail::editTyped(
        *this, [&](TncTable& table) { return detail::setAxisCell(table, *row, axis, value); });
}

MaybeError DatumTable::addDatum(int number) {
    if (byNumber(number)) {
        return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                                KERF_TR_NOOP("datum {1} is already in the datum table"),
                                std::to_string(number));
    }
    return detail::editTyped(*this, [&](TncTable& table) {
        return detail::insertKeyedRow(table, *table.findColumn(m_keyColumn), m_keys, number);
    });
}

MaybeError DatumTable::removeDatum(int number) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    return detail::editTyped(*this, [&](TncTable& table) { return table.removeRow(*row); });
}

}  // namespace kerf::tables
