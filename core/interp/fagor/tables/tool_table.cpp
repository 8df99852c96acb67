#include "core/interp/fagor/tables/tool_table.h"

#include <array>
#include <cmath>

#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

constexpr std::array<std::string_view, 7> kFields = {"D",     "FAM",   "NLIFE", "RLIFE",
                                                     "NOSEA", "NOSEW", "CUTA"};

bool knownField(std::string_view name) {
    for (std::string_view f : kFields) {
        if (f == name) return true;
    }
    return false;
}

int toolNumber(std::string_view key) {
    if (key.size() < 2 || key.size() > 5 || key[0] != 'T') return -1;
    int n = 0;
    for (char c : key.substr(1)) {
        if (c < '0' || c > '9') return -1;
        n = n * 10 + (c - '0');
    }
    return n;
}

bool validValue(std::string_view field, double value) {
    if (field == "D") return value >= 0.0 && value <= 255.0 && value == std::floor(value);
    if (field == "FAM") return value >= 0.0 && value <= 255.0 && value == std::floor(value);
    return true;
}

}  // namespace

Expected<ToolTable> ToolTable::fromText(TableText text) {
    for (const TableRow& row : text.rows()) {
        if (toolNumber(row.key) < 0) {
            return text.error(row.line, 0, KERF_TR_NOOP("'{1}' is not a tool (T<number>)"),
                              {row.key});
        }
        for (const TableField& f : row.fields) {
            if (!knownField(f.name)) {
                return text.error(row.line, f.offset,
                                  KERF_TR_NOOP("unknown field '{1}' (D FAM NLIFE RLIFE NOSEA NOSEW "
                                               "CUTA)"),
                                  {f.name});
            }
            if (!validValue(f.name, f.value)) {
                return text.error(row.line, f.offset,
                                  KERF_TR_NOOP("{1} must be a whole number 0-255"), {f.name});
            }
        }
    }
    ToolTable table;
    table.m_text = std::move(text);
    return table;
}

Expected<ToolTable> ToolTable::parse(std::string_view bytes, std::string fileName) {
    auto text = TableText::parse(bytes, std::move(fileName));
    if (!text) return text.error();
    return fromText(std::move(*text));
}

ToolTable ToolTable::createDefault() {
    ToolTable table;
    table.m_text = TableText::create(
        "%TOOLS,MX,",
        "Kerf FAGOR tools: T<n> D (offset) FAM NLIFE RLIFE NOSEA NOSEW CUTA (degrees, mm)");
    return table;
}

ToolEntry ToolTable::get(int number) const {
    ToolEntry entry;
    entry.number = number;
    entry.offset = number;
    const TableRow* row = m_text.row("T" + std::to_string(number));
    if (row == nullptr) return entry;
    for (const TableField& f : row->fields) {
        if (f.name == "D") entry.offset = static_cast<int>(f.value);
        if (f.name == "FAM") entry.family = static_cast<int>(f.value);
        if (f.name == "NLIFE") entry.nominalLife = f.value;
        if (f.name == "RLIFE") entry.realLife = f.value;
        if (f.name == "NOSEA") entry.noseAngle = f.value;
        if (f.name == "NOSEW") entry.noseWidth = f.value;
        if (f.name == "CUTA") entry.cuttingAngle = f.value;
    }
    return entry;
}

bool ToolTable::set(int number, std::string_view field, double value) {
    if (number < 0 || number > 9999 || !knownField(field) || !validValue(field, value)) {
        return false;
    }
    m_text.set("T" + std::to_string(number), field, value);
    m_modified = true;
    return true;
}

}  // namespace kerf::fagor
