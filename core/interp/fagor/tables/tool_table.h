#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/base/expected.h"
#include "core/interp/fagor/tables/table_text.h"

namespace kerf::fagor {

// One tool: its offset D, family code, nominal and real life, nose angle, nose width and cutting
// angle (angles in degrees, width in mm).
struct ToolEntry {
    int number = 0;
    int offset = 0;           // D
    int family = 0;           // FAM, 0-255 (200-255 special tools)
    double nominalLife = 0;   // NLIFE
    double realLife = 0;      // RLIFE
    double noseAngle = 0;     // NOSEA
    double noseWidth = 0;     // NOSEW
    double cuttingAngle = 0;  // CUTA
};

// The tool table: rows "T<n> D.. FAM.. NLIFE.. RLIFE.. NOSEA.. NOSEW.. CUTA..". A tool without a
// row uses the offset with its own number (T5 -> D5).
class ToolTable {
public:
    static Expected<ToolTable> parse(std::string_view bytes, std::string fileName = {});
    static ToolTable createDefault();
    std::string serialize() const { return m_text.serialize(); }

    ToolEntry get(int number) const;
    // `field` is one of D FAM NLIFE RLIFE NOSEA NOSEW CUTA; false if unknown or out of range.
    bool set(int number, std::string_view field, double value);

    const TableText& text() const { return m_text; }
    bool modified() const { return m_modified; }

private:
    static Expected<ToolTable> fromText(TableText text);

    TableText m_text;
    bool m_modified = false;
};

}  // namespace kerf::fagor
