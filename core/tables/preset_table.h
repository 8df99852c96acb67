#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"
#include "core/tables/axis_values.h"
#include "core/tables/table_unit.h"
#include "core/tables/table_validation.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables {

// One row of PRESET.PR: a reference point in machine coordinates.
struct PresetData {
    int number = 0;       // NR
    std::string comment;  // DOC
    AxisValues axes;      // X Y Z A B C (U V W if present)
    size_t row = 0;       // row in table()

    std::optional<double> axis(char letter) const { return axes.get(letter); }
};

// Typed view of a preset table (.PR), keyed by NR. Columns other than NR, DOC and the axis
// letters (basic rotation, offsets, LOCKED ...) stay in table() untouched.
class PresetTable {
public:
    static Expected<PresetTable> fromTable(TncTable table);
    static Expected<PresetTable> parse(std::string_view bytes, std::string fileName = {});
    static Expected<PresetTable> load(const std::filesystem::path& path);
    MaybeError save(const std::filesystem::path& path) const;
    std::string serialize() const { return m_table.serialize(); }

    // "BEGIN PRESET.PR MM", columns NR DOC X Y Z A B C, preset 0 at +0.
    static std::string createDefault(TableUnit unit = TableUnit::Millimetre);

    const TncTable& table() const { return m_table; }
    const std::vector<PresetData>& presets() const { return m_presets; }
    const PresetData* byNumber(int number) const;
    // The column that holds the basic rotation: SPC, or in an older table without it (iTNC 530)
    // ROT; nothing when the table has neither.
    std::optional<size_t> basicRotationColumn() const;
    // The basic rotation of preset `number` (degrees); 0 when the row, the column or the value
    // is missing.
    double basicRotationDeg(int number) const;

    // No value empties the cell. Each edit leaves the table unchanged if it fails. A table
    // written by an older control may lack columns: a value for an axis or a basic rotation the
    // table has no column for adds that column at the end (empty in the other rows).
    MaybeError setAxis(int number, char axis, std::optional<double> value);
    MaybeError setBasicRotation(int number, double degrees);
    MaybeError addPreset(int number);
    MaybeError removePreset(int number);

private:
    explicit PresetTable(TncTable table) : m_table(std::move(table)) {}

    TncTable m_table;
    std::vector<PresetData> m_presets;
    std::vector<std::optional<RowKey>> m_keys;
};

}  // namespace kerf::tables
