#include "core/interp/fagor/tables/tool_offset_table.h"

#include <cmath>

#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

constexpr std::string_view kFields = "XZFRIK";

// "D17" -> 17, or -1.
int offsetNumber(std::string_view key) {
    if (key.size() < 2 || key.size() > 4 || key[0] != 'D') return -1;
    int n = 0;
    for (char c : key.substr(1)) {
        if (c < '0' || c > '9') return -1;
        n = n * 10 + (c - '0');
    }
    return n;
}

}  // namespace

Expected<ToolOffsetTable> ToolOffsetTable::fromText(TableText text) {
    for (const TableRow& row : text.rows()) {
        const int n = offsetNumber(row.key);
        if (n < 0 || n > kMaxOffset) {
            return text.error(row.line, 0, KERF_TR_NOOP("'{1}' is not a tool offset (D0-D255)"),
                              {row.key});
        }
        for (const TableField& f : row.fields) {
            if (f.name.size() != 1 || kFields.find(f.name[0]) == std::string_view::npos) {
                return text.error(row.line, f.offset,
                                  KERF_TR_NOOP("unknown field '{1}' (X Z F R I K)"), {f.name});
            }
            if (f.name == "F" &&
                (f.value < 0.0 || f.value > 9.0 || f.value != std::floor(f.value))) {
                return text.error(row.line, f.offset,
                                  KERF_TR_NOOP("the location code F must be a whole number 0-9"));
            }
        }
    }
    ToolOffsetTable table;
    table.m_text = std::move(text);
    return table;
}

Expected<ToolOffsetTable> ToolOffsetTable::parse(std::string_view bytes, std::string fileName) {
    auto text = TableText::parse(bytes, std::move(fileName));
    if (!text) return text.error();
    return fromText(std::move(*text));
}

ToolOffsetTable ToolOffsetTable::createDefault() {
    ToolOffsetTable table;
    table.m_text = TableText::create(
        "%TOOL OFFSETS,MX,",
        "Kerf FAGOR tool offsets: D<n> X Z (lengths) F (location code) R (nose radius) I K (wear), "
        "mm, X and I in radius");
    return table;
}

ToolOffset ToolOffsetTable::get(int number) const {
    ToolOffset offset;
    offset.number = number;
    if (number <= 0) return offset;
    const TableRow* row = m_text.row("D" + std::to_string(number));
    if (row == nullptr) return offset;
    for (const TableField& f : row->fields) {
        switch (f.name[0]) {
            case 'X':
                offset.x = f.value;
                break;
            case 'Z':
                offset.z = f.value;
                break;
            case 'R':
                offset.radius = f.value;
                break;
            case 'F':
                offset.location = static_cast<int>(f.value);
                break;
            case 'I':
                offset.wearX = f.value;
                break;
            case 'K':
                offset.wearZ = f.value;
                break;
            default:
                break;
        }
    }
    return offset;
}

bool ToolOffsetTable::set(int number, char field, double value) {
    if (number <= 0 || number > kMaxOffset || kFields.find(field) == std::string_view::npos) {
        return false;
    }
    if (field == 'F' && (value < 0.0 || value > 9.0 || value != std::floor(value))) return false;
    m_text.set("D" + std::to_string(number), std::string(1, field), value);
    m_modified = true;
    return true;
}

}  // namespace kerf::fagor
