#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/base/expected.h"
#include "core/geometry/axes.h"
#include "core/interp/fagor/tables/table_text.h"

namespace kerf::fagor {

// Which zero offset is active: absolute G54-G57 (1-4) or G159 N1-N20, an additive G58/G59 (5, 6)
// on top of it, or a G92 preset (the resulting offset per axis). Survives the end of a program
// and is kept in the table file (row ACTIVE).
struct ZeroOffsetSelection {
    int absolute = 0;     // 0: none
    bool byG159 = false;  // selected with G159 N<absolute>
    int additive = 0;     // 0, 5 (G58) or 6 (G59)
    bool preset = false;  // G92: `presetOffset` is the offset
    Pose presetOffset{};
    friend bool operator==(const ZeroOffsetSelection&, const ZeroOffsetSelection&) = default;
};

// The zero offset table, values in radius and millimetres, referred to machine zero:
//   G54 X0 Z330 ... G59 X0 Z-180    offsets 1-6 (G159 N1-N6 select them too)
//   G159N7 X.. Z.. ... G159N20      offsets 7-20
//   PLC X.. Z..                     the PLC offset, always added
//   ACTIVE G54 G58                  the selection (also "G159 N7", "G92 X.. Z..", none: no row)
class ZeroOffsetTable {
public:
    static constexpr int kCount = 20;

    static Expected<ZeroOffsetTable> parse(std::string_view bytes, std::string fileName = {});
    static ZeroOffsetTable createDefault();
    std::string serialize() const { return m_text.serialize(); }

    // Offset 1-20 (axes without a value are 0).
    Pose offset(int index) const;
    bool setOffset(int index, Axis axis, double value);
    Pose plcOffset() const;
    void setPlcOffset(Axis axis, double value);

    const ZeroOffsetSelection& selection() const { return m_selection; }
    void setSelection(const ZeroOffsetSelection& selection);
    // The offset the selection gives, PLC offset excluded.
    Pose selectedOffset() const;

    static std::string keyFor(int index);
    const TableText& text() const { return m_text; }
    bool modified() const { return m_modified; }

private:
    static Expected<ZeroOffsetTable> fromText(TableText text);
    Pose rowValues(std::string_view key) const;

    TableText m_text;
    ZeroOffsetSelection m_selection;
    bool m_modified = false;
};

}  // namespace kerf::fagor
