#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/base/expected.h"
#include "core/interp/fagor/tables/table_text.h"

namespace kerf::fagor {

// One tool offset (corrector) D: lengths from the holder reference to the theoretical tip along X
// (radius) and Z, nose radius, tip location code (0-9) and the wear of the X and Z lengths.
// Millimetres.
struct ToolOffset {
    int number = 0;
    double x = 0.0;       // X
    double z = 0.0;       // Z
    double radius = 0.0;  // R
    int location = 0;     // F
    double wearX = 0.0;   // I
    double wearZ = 0.0;   // K
};

// The tool offset table: rows "D<n> X.. Z.. F.. R.. I.. K..", n = 0..255. Offsets without a row
// are all zero (as on the control, where every offset exists). D0 is always zero.
class ToolOffsetTable {
public:
    static constexpr int kMaxOffset = 255;

    static Expected<ToolOffsetTable> parse(std::string_view bytes, std::string fileName = {});
    static ToolOffsetTable createDefault();
    std::string serialize() const { return m_text.serialize(); }

    ToolOffset get(int number) const;
    // `field` is one of X Z F R I K. False for D0, numbers out of range or F outside 0-9.
    bool set(int number, char field, double value);

    const TableText& text() const { return m_text; }
    bool modified() const { return m_modified; }

private:
    static Expected<ToolOffsetTable> fromText(TableText text);

    TableText m_text;
    bool m_modified = false;
};

}  // namespace kerf::fagor
