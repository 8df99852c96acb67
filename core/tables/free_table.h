#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables {

// A freely definable table (.TAB) as the NC program sees it through FN 26 TABOPEN,
// FN 27 TABWRITE and FN 28 TABREAD. Rows are addressed by the number in their key (first)
// column, columns by name; a column list is written as in the NC block, "X,Y,Z".
//
// Only numbers go in and out: reading an empty or text cell, writing into a column declared as
// text (or over text), naming an unknown column and addressing a missing row are errors; a
// write never adds a row. Writes change the table in memory; save() puts it on disk. The
// interpreter reads and writes the file through the NC root's file-access layer instead
// (docs/files.md): fromTable() and table().
class FreeTable {
public:
    // FN 26: TABOPEN.
    static Expected<FreeTable> open(const std::filesystem::path& path);
    static Expected<FreeTable> fromTable(TncTable table, std::filesystem::path path = {});

    // FN 28: TABREAD Q1 = row / "X,Y": one value per listed column.
    Expected<std::vector<double>> read(int64_t row, std::string_view columnList) const;
    // FN 27: TABWRITE row / "X,Y" = Q5: values[i] goes to the i-th listed column. Either all
    // values are written or none.
    MaybeError write(int64_t row, std::string_view columnList, std::span<const double> values);

    // Writes the table back to the file it was opened from, atomically.
    MaybeError save() const;
    bool modified() const { return m_modified; }

    const TncTable& table() const { return m_table; }
    const std::filesystem::path& path() const { return m_path; }

private:
    FreeTable(TncTable table, std::filesystem::path path)
        : m_table(std::move(table)), m_path(std::move(path)) {}
    Expected<size_t> findRow(int64_t row) const;
    Expected<std::vector<size_t>> findColumns(std::string_view columnList) const;

    TncTable m_table;
    std::filesystem::path m_path;
    bool m_modified = false;
};

}  // namespace kerf::tables
