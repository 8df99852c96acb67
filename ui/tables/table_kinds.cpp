#include "ui/tables/table_kinds.h"

#include <algorithm>
#include <cctype>

#include "core/interp/fagor/tables/tool_offset_table.h"
#include "core/interp/fagor/tables/tool_table.h"
#include "core/interp/fagor/tables/zero_offset_table.h"
#include "core/tables/datum_table.h"
#include "core/tables/point_table.h"
#include "core/tables/preset_table.h"
#include "core/tables/probe_table.h"
#include "core/tables/table_validation.h"
#include "core/tables/tool_table.h"

namespace kerf::ui {

namespace {

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return text;
}

// Validation errors of a typed view's fromTable, as a list.
template <typename View>
DiagnosticList viewProblems(const tables::TncTable& table) {
    auto view = View::fromTable(table);
    return view ? DiagnosticList{} : DiagnosticList{view.error()};
}

template <typename View>
tables::TncTable viewTable(tables::TncTable table) {
    if (auto view = View::fromTable(table)) return view->table();
    return table;
}

}  // namespace

TableKind tableKindOf(const std::filesystem::path& path) {
    const std::string name = upper(path.filename().string());
    if (name == "FAGOR_TOOL_OFFSETS.TAB") return TableKind::FagorToolOffsets;
    if (name == "FAGOR_ZERO_OFFSETS.TAB") return TableKind::FagorZeroOffsets;
    if (name == "FAGOR_TOOLS.TAB") return TableKind::FagorTools;
    const std::string extension = upper(path.extension().string());
    if (extension == ".T") return TableKind::Tool;
    if (extension == ".PR") return TableKind::Preset;
    if (extension == ".D") return TableKind::Datum;
    if (extension == ".PNT") return TableKind::Point;
    if (extension == ".TP") return TableKind::Probe;
    return TableKind::OtherTnc;
}

bool isFagorTable(TableKind kind) {
    return kind == TableKind::FagorToolOffsets || kind == TableKind::FagorZeroOffsets ||
           kind == TableKind::FagorTools;
}

bool isTableFile(const std::filesystem::path& path) {
    static const std::vector<std::string> extensions = {".T",   ".TCH", ".PR", ".D",
                                                        ".PNT", ".TAB", ".TP"};
    const std::string extension = upper(path.extension().string());
    return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

std::filesystem::path standardTablePath(const std::filesystem::path& ncRoot, TableKind kind) {
    switch (kind) {
        case TableKind::Tool:
            return ncRoot / "TOOL.T";
        case TableKind::Preset:
            return ncRoot / "PRESET.PR";
        case TableKind::Datum:
            return ncRoot / "DATUM.D";
        case TableKind::Point:
            return ncRoot / "POINTS.PNT";
        case TableKind::Probe:
            return ncRoot / "tchprobe.tp";
        case TableKind::FagorToolOffsets:
            return ncRoot / "fagor_tool_offsets.tab";
        case TableKind::FagorZeroOffsets:
            return ncRoot / "fagor_zero_offsets.tab";
        case TableKind::FagorTools:
            return ncRoot / "fagor_tools.tab";
        case TableKind::OtherTnc:
            break;
    }
    return {};
}

std::vector<TableKind> offeredTables(bool lathe) {
    if (lathe) {
        return {TableKind::FagorToolOffsets, TableKind::FagorZeroOffsets, TableKind::FagorTools};
    }
    return {TableKind::Tool, TableKind::Preset, TableKind::Datum, TableKind::Point,
            TableKind::Probe};
}

std::string defaultTableContent(TableKind kind, const std::filesystem::path& path) {
    const std::string stem = upper(path.stem().string());
    auto named = [&stem](std::string_view standard) {
        return stem.empty() ? standard : std::string_view(stem);
    };
    switch (kind) {
        case TableKind::Tool:
            return tables::ToolTable::createDefault();
        case TableKind::Preset:
            return tables::PresetTable::createDefault();
        case TableKind::Datum:
            return tables::DatumTable::createDefault(named("DATUM"));
        case TableKind::Point:
            return tables::PointTable::createDefault(named("POINTS"));
        case TableKind::Probe:
            return tables::ProbeTable::createDefault(named("TCHPROBE"));
        case TableKind::FagorToolOffsets:
            return fagor::ToolOffsetTable::createDefault().serialize();
        case TableKind::FagorZeroOffsets:
            return fagor::ZeroOffsetTable::createDefault().serialize();
        case TableKind::FagorTools:
            return fagor::ToolTable::createDefault().serialize();
        case TableKind::OtherTnc:
            break;
    }
    return {};
}

tables::TncTable typedTncTable(tables::TncTable table, TableKind kind) {
    switch (kind) {
        case TableKind::Tool:
            return viewTable<tables::ToolTable>(std::move(table));
        case TableKind::Preset:
            return viewTable<tables::PresetTable>(std::move(table));
        case TableKind::Datum:
            return viewTable<tables::DatumTable>(std::move(table));
        case TableKind::Point:
            return viewTable<tables::PointTable>(std::move(table));
        case TableKind::Probe:
            return viewTable<tables::ProbeTable>(std::move(table));
        default:
            return table;
    }
}

DiagnosticList validateTncTable(const tables::TncTable& table, TableKind kind) {
    switch (kind) {
        case TableKind::Tool:
            return viewProblems<tables::ToolTable>(table);
        case TableKind::Preset:
            return viewProblems<tables::PresetTable>(table);
        case TableKind::Datum:
            return viewProblems<tables::DatumTable>(table);
        case TableKind::Point:
            return viewProblems<tables::PointTable>(table);
        case TableKind::Probe:
            return viewProblems<tables::ProbeTable>(table);
        default:
            return tables::checkNumericCells(table);
    }
}

}  // namespace kerf::ui
