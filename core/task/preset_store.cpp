#include "core/task/preset_store.h"

#include <string>
#include <system_error>

#include "core/tables/preset_table.h"

namespace kerf::task {

std::array<std::optional<double>, kAxisCount> PresetStore::read() const {
    std::array<std::optional<double>, kAxisCount> values{};
    std::error_code error;
    if (!std::filesystem::exists(m_file, error)) return values;
    const auto table = tables::PresetTable::load(m_file);
    if (!table) return values;
    const tables::PresetData* row = table->byNumber(0);
    if (row == nullptr) return values;
    for (int i = 0; i < kAxisCount; ++i)
        values[static_cast<size_t>(i)] = row->axis(axisLetter(static_cast<Axis>(i)));
    return values;
}

MaybeError PresetStore::write(const Pose& origin, AxisMask axes) const {
    std::error_code error;
    auto table = std::filesystem::exists(m_file, error)
                     ? tables::PresetTable::load(m_file)
                     : tables::PresetTable::parse(tables::PresetTable::createDefault(),
                                                  m_file.filename().string());
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
    return table->save(m_file);
}

}  // namespace kerf::task
