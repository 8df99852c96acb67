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

// One row of a point table (.PNT), used by SEL PATTERN / CYCL CALL PAT.
struct PointData {
    int number = 0;      // NR
    AxisValues axes;     // X Y Z (plane: hole centre or cycle start; tool axis: surface)
    bool fade = false;   // FADE: the point is skipped
    bool clear = false;  // CLEAR: retract to the clearance height after this point
    size_t row = 0;      // row in table()

    std::optional<double> axis(char letter) const { return axes.get(letter); }
};

// Typed view of a point table, keyed by NR. FADE and CLEAR hold "Y" (or "1") when set, nothing
// (or "N", "0") when not.
class PointTable {
public:
    static Expected<PointTable> fromTable(TncTable table);
    static Expected<PointTable> parse(std::string_view bytes, std::string fileName = {});
    static Expected<PointTable> load(const std::filesystem::path& path);
    MaybeError save(const std::filesystem::path& path) const;
    std::string serialize() const { return m_table.serialize(); }

    // "BEGIN <name>.PNT MM", columns NR X Y Z FADE CLEAR, no points.
    static std::string createDefault(std::string_view name = "POINTS",
                                     TableUnit unit = TableUnit::Millimetre);

    const TncTable& table() const { return m_table; }
    const std::vector<PointData>& points() const { return m_points; }
    const PointData* byNumber(int number) const;

    // No value empties the cell. Each edit leaves the table unchanged if it fails.
    MaybeError setAxis(int number, char axis, std::optional<double> value);
    MaybeError setFade(int number, bool fade);
    MaybeError setClear(int number, bool clear);
    MaybeError addPoint(int number);
    MaybeError removePoint(int number);

private:
    explicit PointTable(TncTable table) : m_table(std::move(table)) {}
    MaybeError setFlag(int number, std::string_view column, bool value);

    TncTable m_table;
    std::vector<PointData> m_points;
    std::vector<std::optional<RowKey>> m_keys;
};

}  // namespace kerf::tables
