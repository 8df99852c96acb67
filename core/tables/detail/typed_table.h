#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "core/base/expected.h"
#include "core/tables/table_file.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables::detail {

// The plumbing every typed view (ToolTable, PresetTable ...) shares: each has
// `static Expected<View> fromTable(TncTable)` and `const TncTable& table() const`.

template <typename View>
Expected<View> parseTyped(std::string_view bytes, std::string fileName) {
    auto table = TncTable::parse(bytes, std::move(fileName));
    if (!table) return table.error();
    return View::fromTable(std::move(*table));
}

template <typename View>
Expected<View> loadTyped(const std::filesystem::path& path) {
    auto table = loadTable(path);
    if (!table) return table.error();
    return View::fromTable(std::move(*table));
}

// Applies `edit` to a copy of the table and keeps it only if the result still validates, so a
// failed edit leaves the view unchanged.
template <typename View, typename Edit>
MaybeError editTyped(View& view, Edit&& edit) {
    TncTable copy = view.table();
    if (MaybeError error = edit(copy)) return error;
    auto rebuilt = View::fromTable(std::move(copy));
    if (!rebuilt) return rebuilt.error();
    view = std::move(*rebuilt);
    return std::nullopt;
}

}  // namespace kerf::tables::detail
