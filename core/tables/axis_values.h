#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace kerf::tables {

class TncTable;

// Axis letters a preset, datum or point table may have columns for.
inline constexpr std::string_view kAxisLetters = "XYZABCUVW";

// One value per axis letter; an empty cell (or a missing column) has no value, which for a
// datum means "no shift on this axis", unlike 0.
class AxisValues {
public:
    std::optional<double> get(char axis) const;
    void set(char axis, std::optional<double> value);

    // Reads the columns named X, Y, Z, A, B, C, U, V, W of a row.
    static AxisValues fromRow(const TncTable& table, size_t row);

private:
    std::array<std::optional<double>, kAxisLetters.size()> m_values{};
};

}  // namespace kerf::tables
