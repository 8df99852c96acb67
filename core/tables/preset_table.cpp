#include "core/tables/preset_table.h"

#include "core/tables/detail/axis_columns.h"
#include "core/tables/detail/keyed_rows.h"
#include "core/tables/detail/typed_table.h"

namespace kerf::tables {

namespace {

constexpr std::string_view kKey = "NR";
constexpr std::string_view kBasicRotation = "SPC";
constexpr const char* kMissing = KERF_TR_NOOP("preset {1} is not in the preset table");

const std::vector<detail::ColumnSpec>& presetColumns() {
    static const std::vector<detail::ColumnSpec> columns = [] {
        std::vector<detail::ColumnSpec> specs = {detail::otherColumn("NR", 8),
                                                 detail::textColumn("DOC", 17)};
        detail::appendAxisColumns(specs, "XYZABC");
        // The basic rotation of the preset (404 and 400-402, 414 with Q305 > 0 write it).
        specs.push_back(detail::numberColumn(std::string(kBasicRotation), detail::kAxisColumnWidth,
                                             true, "+0"));
        return specs;
    }();
    return columns;
}

// The table with `name` appended if it lacks it, as a new table would have it (an axis letter
// of any axis the machines know, or SPC).
MaybeError appendMissingColumn(TncTable& table, std::string_view name) {
    if (table.findColumn(name)) return std::nullopt;
    std::vector<detail::ColumnSpec> known = presetColumns();
    detail::appendAxisColumns(known, "UVW");
    for (const detail::ColumnSpec& spec : known) {
        if (spec.name == name) return table.appendColumn(spec.name, spec.width, spec.format);
    }
    return table.headerError(KERF_TR_NOOP("the table has no column {1}"), {std::string(name)});
}

}  // namespace

Expected<PresetTable> PresetTable::fromTable(TncTable table) {
    if (MaybeError missing = requireColumn(table, kKey)) return *missing;
    detail::applyColumnSpecs(table, presetColumns());
    detail::applyAxisFormats(table);
    DiagnosticList errors;
    auto keys = detail::validateKeyedTable(table, kKey, errors);
    if (!errors.empty()) return errors.front();

    PresetTable result(std::move(table));
    const TncTable& t = result.m_table;
    auto doc = t.findColumn("DOC");
    for (size_t row = 0; row < keys.size(); ++row) {
        PresetData preset;
        preset.number = keys[row]->number;
        preset.comment = doc ? std::string(t.cell(row, *doc)) : std::string();
        preset.axes = AxisValues::fromRow(t, row);
        preset.row = row;
        result.m_presets.push_back(std::move(preset));
    }
    result.m_keys = std::move(keys);
    return result;
}

Expected<PresetTable> PresetTable::parse(std::string_view bytes, std::string fileName) {
    return detail::parseTyped<PresetTable>(bytes, std::move(fileName));
}

Expected<PresetTable> PresetTable::load(const std::filesystem::path& path) {
    return detail::loadTyped<PresetTable>(path);
}

MaybeError PresetTable::save(const std::filesystem::path& path) const {
    return saveTable(m_table, path);
}

std::string PresetTable::createDefault(TableUnit unit) {
    return detail::buildTableText("PRESET", "PR", unit, presetColumns(), {{"0"}});
}

const PresetData* PresetTable::byNumber(int number) const {
    for (const PresetData& preset : m_presets) {
        if (preset.number == number) return &preset;
    }
    return nullptr;
}

std::optional<size_t> PresetTable::basicRotationColumn() const {
    if (auto column = m_table.findColumn(kBasicRotation)) return column;
    return m_table.findColumn("ROT");
}

double PresetTable::basicRotationDeg(int number) const {
    const PresetData* preset = byNumber(number);
    const auto column = basicRotationColumn();
    if (preset == nullptr || !column) return 0.0;
    return m_table.number(preset->row, *column).value_or(0.0);
}

MaybeError PresetTable::setAxis(int number, char axis, std::optional<double> value) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    return detail::editTyped(*this, [&](TncTable& table) -> MaybeError {
        const std::string_view name(&axis, 1);
        // Emptying a cell the table does not have leaves it as it is.
        if (!value && !table.findColumn(name)) return std::nullopt;
        if (MaybeError failed = appendMissingColumn(table, name)) return failed;
        return detail::setAxisCell(table, *row, axis, value);
    });
}

MaybeError PresetTable::setBasicRotation(int number, double degrees) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    const std::optional<size_t> existing = basicRotationColumn();
    return detail::editTyped(*this, [&](TncTable& table) -> MaybeError {
        if (!existing) {
            if (MaybeError failed = appendMissingColumn(table, kBasicRotation)) return failed;
        }
        return table.setNumber(*row, existing ? *existing : *table.findColumn(kBasicRotation),
                               degrees);
    });
}

MaybeError PresetTable::addPreset(int number) {
    if (byNumber(number)) {
        return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                                KERF_TR_NOOP("preset {1} is already in the preset table"),
                                std::to_string(number));
    }
    return detail::editTyped(*this, [&](TncTable& table) {
        return detail::insertKeyedRow(table, *table.findColumn(kKey), m_keys, number);
    });
}

MaybeError PresetTable::removePreset(int number) {
    auto row = detail::rowOfKey(m_keys, m_table, number, kMissing);
    if (!row) return row.error();
    return detail::editTyped(*this, [&](TncTable& table) { return table.removeRow(*row); });
}

}  // namespace kerf::tables
