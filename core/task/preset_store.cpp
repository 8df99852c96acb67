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

MaybeError PresetStore::write(const Pose& origin, AxisMask axes) const {
    std::error_code error;
    const bool exists = std::filesystem::exists(std::filesystem::symlink_status(m_file, error));
    const auto bytes = exists ? m_root.read(m_file) : tables::PresetTable::createDefault();
    if (!bytes) return bytes.error();
    auto table = tables::PresetTable::parse(*bytes, m_file.filename().string());
    if (!table) return table.error();
    if (table->byNumber(0) == nullptr) {
        if (MaybeError failed = table->addPreset(0)) return failed;
    }
    for (int i = 0; i < kAxisCount; ++i) {
        const auto axis = static_cast<Axis>(i);
        const char letter = axisLetter(axis);
        if ((axes & axisBit(axis)) == 0 || !table->table().findColumn(std::string(1, letter)))
            continue;
        if (MaybeError failed = table->setAxis(0, letter, origin[axis])) return failed;
    }
    return m_root.replace(m_file, table->serialize());
}

}  // namespace kerf::task
