#include "core/task/preset_store.h"

#include <string>
#include <system_error>

#include "core/tables/preset_table.h"

namespace kerf::task {

std::array<std::optional<double>, kAxisCount> PresetStore::read() const {
    std::array<std::optional<double>, kAxisCount> values{};
    std::error_code error;
    if (!std::filesystem::exists(m_file, error)) return values;
    const auto bytes = m_root.read(m_file);
    if (!bytes) return values;
    const auto table = tables::PresetTable::parse(*bytes, m_file.string());
    if (!table) return values;
    const tables::PresetData* row = table->byNumber(0);
    if (row == nullptr) return values;
    for (int i = 0; i < kAxisCount; ++i)
        values[static_cast<size_t>(i)] = row->axis(axisLetter(static_cast<Axis>(i)));
    return values;
}

double PresetStore::basicRotationDeg() const {
    std::error_code error;
    if (!std::filesystem::exists(m_file, error)) return 0.0;
    const auto bytes = m_root.read(m_file);
    if (!bytes) return 0.0;
    const auto table = tables::PresetTable::parse(*bytes, m_file.string());
    return table ? table->basicRotationDeg(0) : 0.0;
}

namespace {

// The table with a row 0 (created with the standard columns if missing), or why it cannot be read.
Expected<tables::PresetTable> tableWithRowZero(const program::NcRoot& root,
                                               const std::filesystem::path& file) {
    std::error_code error;
    const bool exists = std::filesystem::exists(std::filesystem::symlink_status(file, error));
    const auto bytes = exists ? root.read(file) : tables::PresetTable::createDefault();
    if (!bytes) return bytes.error();
    auto table = tables::PresetTable::parse(*bytes, file.filename().string());
    if (!table) return table.error();
    if (table->byNumber(0) == nullptr) {
        if (MaybeError failed = table->addPreset(0)) return *failed;
    }
    return table;
}

}  // namespace

MaybeError PresetStore::write(const Pose& origin, AxisMask axes) const {
    auto table = tableWithRowZero(m_root, m_file);
    if (!table) return table.error();
    for (int i = 0; i < kAxisCount; ++i) {
        const auto axis = static_cast<Axis>(i);
        if ((axes & axisBit(axis)) == 0) continue;
        if (MaybeError failed = table->setAxis(0, axisLetter(axis), origin[axis])) return failed;
    }
    return m_root.replace(m_file, table->serialize());
}

MaybeError PresetStore::writeBasicRotation(double degrees) const {
    auto table = tableWithRowZero(m_root, m_file);
    if (!table) return table.error();
    if (MaybeError failed = table->setBasicRotation(0, degrees)) return failed;
    return m_root.replace(m_file, table->serialize());
}

}  // namespace kerf::task
