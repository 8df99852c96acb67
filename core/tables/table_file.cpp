#include "core/tables/table_file.h"

#include "core/base/atomic_file.h"

namespace kerf::tables {

Expected<TncTable> loadTable(const std::filesystem::path& path) {
    auto bytes = readWholeFile(path);
    if (!bytes) return bytes.error();
    return TncTable::parse(*bytes, path.string());
}

MaybeError saveTable(const TncTable& table, const std::filesystem::path& path) {
    return writeFileAtomically(path, table.serialize());
}

}  // namespace kerf::tables
