#include "core/tables/probe_table.h"

#include <array>

#include "core/tables/detail/column_spec.h"
#include "core/tables/detail/keyed_rows.h"
#include "core/tables/detail/typed_table.h"
#include "core/tables/tnc_number.h"

namespace kerf::tables {

namespace {

constexpr std::string_view kKey = "NO";

// Defaults of a new row (our choice; the spec names no values): a slow probing feed, a short
// probing path and a small clearance are the safe side for a probe nobody has set up yet.
const std::vector<detail::ColumnSpec>& probeColumns() {
    static const std::vector<detail::ColumnSpec> columns = {
        detail::integerColumn("NO", 5),
        detail::textColumn("TYPE", 11, "TS460"),
        detail::numberColumn("CAL_OF1", 11, true, "+0"),
        detail::numberColumn("CAL_OF2", 11, true, "+0"),
        detail::numberColumn("CAL_ANG", 9, true, "+0"),
        detail::numberColumn("F", 9, false, "1000"),
        detail::numberColumn("FMAX", 9, false, "3000"),
        detail::numberColumn("DIST", 8, false, "20"),
        detail::numberColumn("SET_UP", 8, false, "2"),
        detail::textColumn("F_PREPOS", 14, "FMAX_PROBE"),
        detail::textColumn("TRACK", 7, "OFF"),
        detail::textColumn("SERIAL", 12),
    };
    return columns;
}

struct Limit {
    std::string_view column;
    bool positive;  // > 0; otherwise >= 0
};
constexpr std::array<Limit, 4> kLimits = {{
    {"F", true},
    {"FMAX", false},
    {"DIST", true},
    {"SET_UP", false},
}};

// Column value or its default when the cell is empty; checks the sign rule.
double readLimited(const TncTable& table, size_t row, const Limit& limit, DiagnosticList& errors) {
    auto column = table.findColumn(limit.column);
    if (!column) return 0.0;
    auto value = table.number(row, *column);
    if (!value) value = parseTncNumber(table.columnFormat(*column).defaultValue);
    const double v = value.value_or(0.0);
    if (limit.positive ? v <= 0.0 : v < 0.0) {
        errors.push_back(table.cellError(
            row, *column,
            limit.positive ? KERF_TR_NOOP("column {1} must be greater than 0, not {2}")
                           : KERF_TR_NOOP("column {1} must not be negative, not {2}"),
            {std::string(limit.column), std::string(table.cell(row, *column))}));
    }
    return v;
}

// A text column holding one of two words (empty: the first). True for the second.
bool readChoice(const TncTable& table, size_t row, std::string_view name, std::string_view first,
                std::string_view second, DiagnosticList& errors) {
    auto column = table.findColumn(name);
    if (!column) return false;
    const std::string_view text = table.cell(row, *column);
    if (text.empty() || text == first) return false;
    if (text == second) return true;
    errors.push_back(table.cellError(
        row, *column, KERF_TR_NOOP("column {1} needs {2} or {3}, not \"{4}\""),
        {std::string(name), std::string(first), std::string(second), std::string(text)}));
    return false;
}

double optionalNumber(const TncTable& table, size_t row, std::string_view name) {
    auto column = table.findColumn(name);
    return column ? table.number(row, *column).value_or(0.0) : 0.0;
}

std::string text(const TncTable& table, size_t row, std::string_view name) {
    auto column = table.findColumn(name);
    return column ? std::string(table.cell(row, *column)) : std::string();
}

// TYPE: a model of the catalogue; an empty cell (or no column) is the default row's TS460.
const ProbeType* readType(const TncTable& table, size_t row, DiagnosticList& errors) {
    auto column = table.findColumn("TYPE");
    const std::string_view cell = column ? table.cell(row, *column) : std::string_view();
    if (cell.empty()) return findProbeType("TS460");
    if (const ProbeType* type = findProbeType(cell)) return type;
    std::string known;
    for (const ProbeType& type : probeTypes())
        known += (known.empty() ? "" : ", ") + std::string(type.name);
    errors.push_back(table.cellError(
        row, *column, KERF_TR_NOOP("column TYPE: unknown probe \"{1}\" (known: {2})"),
        {std::string(cell), known}));
    return nullptr;
}

}  // namespace

Expected<ProbeTable> ProbeTable::fromTable(TncTable table) {
    if (MaybeError missing = requireColumn(table, kKey)) return *missing;
    detail::applyColumnSpecs(table, probeColumns());
    DiagnosticList errors;
    auto keys = detail::validateKeyedTable(table, kKey, errors);
    std::vector<ProbeData> probes;
    for (size_t row = 0; row < table.rowCount(); ++row) {
        ProbeData probe;
        probe.number = keys[row] ? keys[row]->number : 0;
        probe.type = text(table, row, "TYPE");
        probe.model = readType(table, row, errors);
        probe.centreOffsetMain = optionalNumber(table, row, "CAL_OF1");
        probe.centreOffsetSecondary = optionalNumber(table, row, "CAL_OF2");
        probe.calibrationAngle = optionalNumber(table, row, "CAL_ANG");
        probe.probingFeed = readLimited(table, row, kLimits[0], errors);
        probe.rapidFeed = readLimited(table, row, kLimits[1], errors);
        probe.maxProbingPath = readLimited(table, row, kLimits[2], errors);
        probe.setUpClearance = readLimited(table, row, kLimits[3], errors);
        probe.prepositionAtMachineRapid =
            readChoice(table, row, "F_PREPOS", "FMAX_PROBE", "FMAX_MACHINE", errors);
        probe.track = readChoice(table, row, "TRACK", "OFF", "ON", errors);
        if (probe.track && probe.model != nullptr &&
            probe.model->orientation != ProbeOrientation::Any) {
            const auto column = table.findColumn("TRACK");
            errors.push_back(table.cellError(
                row, *column,
                KERF_TR_NOOP("TRACK ON needs a probe the spindle can turn to any angle; {1} "
                             "cannot be"),
                {std::string(probe.model->name)}));
        }
        probe.serial = text(table, row, "SERIAL");
        probe.row = row;
        probes.push_back(std::move(probe));
    }
    if (!errors.empty()) return errors.front();
    ProbeTable result(std::move(table));
    result.m_probes = std::move(probes);
    return result;
}

Expected<ProbeTable> ProbeTable::parse(std::string_view bytes, std::string fileName) {
    return detail::parseTyped<ProbeTable>(bytes, std::move(fileName));
}

Expected<ProbeTable> ProbeTable::load(const std::filesystem::path& path) {
    return detail::loadTyped<ProbeTable>(path);
}

MaybeError ProbeTable::save(const std::filesystem::path& path) const {
    return saveTable(m_table, path);
}

std::string ProbeTable::createDefault(std::string_view name, TableUnit unit) {
    return detail::buildTableText(name, "TP", unit, probeColumns(), {{"1"}});
}

const ProbeData* ProbeTable::byNumber(int number) const {
    for (const ProbeData& probe : m_probes) {
        if (probe.number == number) return &probe;
    }
    return nullptr;
}

MaybeError ProbeTable::setCentreOffset(int number, double main, double secondary) {
    const ProbeData* probe = byNumber(number);
    if (probe == nullptr) {
        return Diagnostic::make(Severity::Error, "table", m_table.fileName(), 0, 0,
                                KERF_TR_NOOP("probe {1} is not in the touch-probe table"),
                                std::to_string(number));
    }
    const size_t row = probe->row;
    return detail::editTyped(*this, [&](TncTable& table) -> MaybeError {
        const std::pair<const char*, double> cells[] = {{"CAL_OF1", main}, {"CAL_OF2", secondary}};
        for (const auto& [name, value] : cells) {
            if (!table.findColumn(name)) {
                for (const detail::ColumnSpec& spec : probeColumns()) {
                    if (spec.name != name) continue;
                    if (MaybeError failed = table.appendColumn(name, spec.width, spec.format))
                        return failed;
                }
            }
            if (MaybeError failed = table.setNumber(row, *table.findColumn(name), value))
                return failed;
        }
        return std::nullopt;
    });
}

}  // namespace kerf::tables
