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

// One row of a datum table (.D): a zero offset relative to the active preset.
struct DatumData {
    int number = 0;       // D (or NR)
    std::string comment;  // DOC
    AxisValues axes;      // X Y Z A B C (U V W if present); empty = no shift
    size_t row = 0;       // row in table()

    std::optional<double> axis(char letter) const { return axes.get(letter); }
};

// Typed view of a datum table (.D), keyed by D (the TNC's column) or, failing that, NR. Other
// columns stay in table() untouched.
class DatumTable {
public:
    static Expected<DatumTable> fromTable(TncTable table);
    static Expected<DatumTable> parse(std::string_view bytes, std::string fileName = {});
    static Expected<DatumTable> load(const std::filesystem::path& path);
    MaybeError save(const std::filesystem::path& path) const;
    std::string serialize() const { return m_table.serialize(); }

    // "BEGIN <name>.D MM", columns D X Y Z A B C DOC, datum 0 at +0.
    static std::string createDefault(std::string_view name = "DATUM",
                                     TableUnit unit = TableUnit::Millimetre);

    const TncTable& table() const { return m_table; }
    const std::vector<DatumData>& datums() const { return m_datums; }
    const DatumData* byNumber(int number) const;

    // No value empties the cell. Each edit leaves the table unchanged if it fails.
    MaybeError setAxis(int number, char axis, std::optional<double> value);
    MaybeError addDatum(int number);
    MaybeError removeDatum(int number);

private:
    explicit DatumTable(TncTable table) : m_table(std::move(table)) {}

    TncTable m_table;
    std::vector<DatumData> m_datums;
    std::vector<std::optional<RowKey>> m_keys;
    std::string m_keyColumn;
};

}  // namespace kerf::tables
