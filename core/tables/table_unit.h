#pragma once

#include <cstdint>
#include <string_view>

namespace kerf::tables {

// Length unit named on a table's BEGIN line.
enum class TableUnit : uint8_t { Millimetre, Inch };

inline std::string_view unitKeyword(TableUnit unit) {
    return unit == TableUnit::Inch ? "INCH" : "MM";
}

}  // namespace kerf::tables
