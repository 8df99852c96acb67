#include "core/interp/fagor/tables/zero_offset_table.h"

#include <cmath>

#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

// G54 -> 1 ... G59 -> 6, G159N7 -> 7 ... G159N20 -> 20, else 0.
int indexOfKey(std::string_view key) {
    for (int i = 1; i <= ZeroOffsetTable::kCount; ++i) {
        if (key == ZeroOffsetTable::keyFor(i)) return i;
    }
    return 0;
}

bool isAxisField(const TableField& f) {
    return f.name.size() == 1 && axisFromLetter(f.name[0]).has_value();
}

// A field value as a whole G or N number, -1 when it is none: a value beyond int (G99999999999) may
// not be converted (undefined behaviour).
int asSmallWhole(double value) {
    return value >= 0.0 && value <= 9999.0 && value == std::floor(value) ? static_cast<int>(value)
                                                                         : -1;
}

}  // namespace

std::string ZeroOffsetTable::keyFor(int index) {
    if (index >= 1 && index <= 6) return "G" + std::to_string(53 + index);
    return "G159N" + std::to_string(index);
}

Expected<ZeroOffsetTable> ZeroOffsetTable::fromText(TableText text) {
    ZeroOffsetTable table;
    for (const TableRow& row : text.rows()) {
        if (row.key == "ACTIVE") {
            ZeroOffsetSelection s;
            for (size_t i = 0; i < row.fields.size(); ++i) {
                const TableField& f = row.fields[i];
                const int g = asSmallWhole(f.value);
                if (f.name == "G" && g >= 54 && g <= 57 && s.absolute == 0 && !s.preset) {
                    s.absolute = g - 53;
                } else if (f.name == "G" && (g == 58 || g == 59) && s.additive == 0 && !s.byG159 &&
                           !s.preset) {
                    s.additive = g - 53;
                } else if (f.name == "G" && g == 159 && i + 1 < row.fields.size() &&
                           row.fields[i + 1].name == "N" && s.absolute == 0) {
                    s.absolute = asSmallWhole(row.fields[++i].value);
                    s.byG159 = true;
                    if (s.absolute < 1 || s.absolute > kCount) {
                        return text.error(row.line, row.fields[i].offset,
                                          KERF_TR_NOOP("G159 selects offsets N1-N20"));
                    }
                } else if (f.name == "G" && g == 92 && s.absolute == 0) {
                    s.preset = true;
                } else if (f.name == "G" && g == 53) {
                    // No offset.
                } else if (s.preset && isAxisField(f)) {
                    s.presetOffset[*axisFromLetter(f.name[0])] = f.value;
                } else {
                    return text.error(row.line, f.offset,
                                      KERF_TR_NOOP("'{1}' cannot be part of the ACTIVE selection"),
                                      {f.name + formatTableNumber(f.value)});
                }
            }
            table.m_selection = s;
            continue;
        }
        if (row.key != "PLC" && indexOfKey(row.key) == 0) {
            return text.error(row.line, 0,
                              KERF_TR_NOOP("'{1}' is not a zero offset (G54-G59, G159N7-G159N20, "
                                           "PLC, ACTIVE)"),
                              {row.key});
        }
        for (const TableField& f : row.fields) {
            if (!isAxisField(f)) {
                return text.error(row.line, f.offset, KERF_TR_NOOP("'{1}' is not an axis"),
                                  {f.name});
            }
        }
    }
    table.m_text = std::move(text);
    return table;
}

Expected<ZeroOffsetTable> ZeroOffsetTable::parse(std::string_view bytes, std::string fileName) {
    auto text = TableText::parse(bytes, std::move(fileName));
    if (!text) return text.error();
    return fromText(std::move(*text));
}

ZeroOffsetTable ZeroOffsetTable::createDefault() {
    ZeroOffsetTable table;
    table.m_text = TableText::create(
        "%ZERO OFFSETS,MX,",
        "Kerf FAGOR zero offsets from machine zero: G54-G59, G159N7-G159N20, PLC; mm, X in radius");
    return table;
}

Pose ZeroOffsetTable::rowValues(std::string_view key) const {
    Pose values{};
    if (const TableRow* row = m_text.row(key)) {
        for (const TableField& f : row->fields) {
            if (auto axis = axisFromLetter(f.name[0])) values[*axis] = f.value;
        }
    }
    return values;
}

Pose ZeroOffsetTable::offset(int index) const {
    if (index < 1 || index > kCount) return Pose{};
    return rowValues(keyFor(index));
}

bool ZeroOffsetTable::setOffset(int index, Axis axis, double value) {
    if (index < 1 || index > kCount) return false;
    m_text.set(keyFor(index), std::string(1, axisLetter(axis)), value);
    m_modified = true;
    return true;
}

Pose ZeroOffsetTable::plcOffset() const {
    return rowValues("PLC");
}

void ZeroOffsetTable::setPlcOffset(Axis axis, double value) {
    m_text.set("PLC", std::string(1, axisLetter(axis)), value);
    m_modified = true;
}

Pose ZeroOffsetTable::selectedOffset() const {
    if (m_selection.preset) return m_selection.presetOffset;
    Pose result = offset(m_selection.absolute);
    if (m_selection.additive != 0) {
        const Pose add = offset(m_selection.additive);
        for (size_t i = 0; i < result.values.size(); ++i)
            result.values[i] += add.values[i];
    }
    return result;
}

void ZeroOffsetTable::setSelection(const ZeroOffsetSelection& selection) {
    if (selection == m_selection) return;
    m_selection = selection;
    std::string fields;
    if (selection.preset) {
        fields = "G92";
        for (int i = 0; i < kAxisCount; ++i) {
            const double v = selection.presetOffset.values[static_cast<size_t>(i)];
            if (v == 0.0) continue;
            fields += " ";
            fields += axisLetter(static_cast<Axis>(i));
            fields += formatTableNumber(v);
        }
    } else if (selection.byG159) {
        fields = "G159 N" + std::to_string(selection.absolute);
    } else {
        if (selection.absolute != 0) fields = "G" + std::to_string(53 + selection.absolute);
        if (selection.additive != 0) {
            if (!fields.empty()) fields += " ";
            fields += "G" + std::to_string(53 + selection.additive);
        }
        if (fields.empty()) fields = "G53";
    }
    m_text.replaceRow("ACTIVE", fields);
    m_modified = true;
}

}  // namespace kerf::fagor
