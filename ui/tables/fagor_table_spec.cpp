#include "ui/tables/fagor_table_spec.h"

#include "core/interp/fagor/tables/tool_offset_table.h"
#include "core/interp/fagor/tables/tool_table.h"
#include "core/interp/fagor/tables/zero_offset_table.h"

namespace kerf::ui {

namespace {

// Parses the text again through the typed table, which knows every rule of the format.
template <typename Table>
MaybeError reparse(const fagor::TableText& text) {
    auto table = Table::parse(text.serialize(), text.fileName());
    if (!table) return table.error();
    return std::nullopt;
}

FagorColumn length(std::string field) {
    return FagorColumn{std::move(field), QStringLiteral("mm")};
}

FagorColumn whole(std::string field, double minimum, double maximum) {
    return FagorColumn{std::move(field), QString(), true, minimum, maximum};
}

FagorColumn other(std::string field, QString unit) {
    return FagorColumn{std::move(field), std::move(unit)};
}

}  // namespace

FagorTableSpec fagorTableSpec(TableKind kind, std::string_view axisLetters) {
    FagorTableSpec spec;
    if (kind == TableKind::FagorToolOffsets) {
        // X and I are radius values, as the table's own comment says.
        spec.keyPrefix = "D";
        spec.lastKey = fagor::ToolOffsetTable::kMaxOffset;
        spec.columns = {length("X"),      length("Z"), length("R"),
                        whole("F", 0, 9), length("I"), length("K")};
        spec.validate = reparse<fagor::ToolOffsetTable>;
    } else if (kind == TableKind::FagorZeroOffsets) {
        for (int i = 1; i <= fagor::ZeroOffsetTable::kCount; ++i)
            spec.fixedKeys.push_back(fagor::ZeroOffsetTable::keyFor(i));
        spec.fixedKeys.emplace_back("PLC");
        for (char letter : axisLetters) {
            const bool rotary = letter == 'A' || letter == 'B' || letter == 'C';
            spec.columns.push_back(other(std::string(1, letter),
                                         rotary ? QStringLiteral("\u00b0") : QStringLiteral("mm")));
        }
        spec.validate = reparse<fagor::ZeroOffsetTable>;
    } else if (kind == TableKind::FagorTools) {
        // T0 is "no tool" on the 8035: new tools start at T1 (firstKey's default), as D0 is no
        // offset and the offsets start at D1.
        spec.keyPrefix = "T";
        spec.lastKey = 9999;  // the longest key the table reads, "T9999"
        // Tool life is in minutes or in pieces, as the machine is set up: no unit.
        spec.columns = {whole("D", 0, 255),
                        whole("FAM", 0, 255),
                        other("NLIFE", QString()),
                        other("RLIFE", QString()),
                        other("NOSEA", QStringLiteral("\u00b0")),
                        other("NOSEW", QStringLiteral("mm")),
                        other("CUTA", QStringLiteral("\u00b0"))};
        spec.validate = reparse<fagor::ToolTable>;
    }
    return spec;
}

}  // namespace kerf::ui
