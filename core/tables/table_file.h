#pragma once

#include <filesystem>

#include "core/base/expected.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables {

// Reads and parses a table file; diagnostics name the path.
Expected<TncTable> loadTable(const std::filesystem::path& path);

// Writes the table so that a crash leaves the old or the new file, never a mix.
MaybeError saveTable(const TncTable& table, const std::filesystem::path& path);

}  // namespace kerf::tables
