#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/tables/tnc_table.h"

namespace kerf::ui {

// The tables the HMI edits. TNC tables are fixed-width files known by their extension; the
// FAGOR tables are key-and-field files known by their name in the NC root (docs/fagor.md).
enum class TableKind {
    Tool,              // TOOL.T
    Preset,            // PRESET.PR
    Datum,             // *.D
    Point,             // *.PNT
    Probe,             // tchprobe.tp
    OtherTnc,          // any other TNC table (.TCH, .TAB ...): plain cells
    FagorToolOffsets,  // fagor_tool_offsets.tab
    FagorZeroOffsets,  // fagor_zero_offsets.tab
    FagorTools,        // fagor_tools.tab
};

TableKind tableKindOf(const std::filesystem::path& path);
bool isFagorTable(TableKind kind);
// True for the files the table editor opens rather than the program editor.
bool isTableFile(const std::filesystem::path& path);

// The file of a kind in the NC root: TOOL.T, PRESET.PR, DATUM.D, POINTS.PNT, tchprobe.tp and
// the FAGOR file names.
std::filesystem::path standardTablePath(const std::filesystem::path& ncRoot, TableKind kind);
// The kinds the "Tables" page offers: the TNC tables on a mill, the FAGOR tables on a lathe.
std::vector<TableKind> offeredTables(bool lathe);

// Text of a new table of this kind, as a fresh control has it; empty for OtherTnc. Datum,
// point and touch-probe tables name themselves after `path`'s stem (FIX.D: "BEGIN FIX.D MM").
std::string defaultTableContent(TableKind kind, const std::filesystem::path& path = {});

// A TNC table with the column formats of its typed view, so that numeric columns refuse text as
// it is typed. A file the typed view rejects stays untyped, to be repaired.
tables::TncTable typedTncTable(tables::TncTable table, TableKind kind);
// The whole-table check of the typed view (unique keys, numbers, allowed words ...).
DiagnosticList validateTncTable(const tables::TncTable& table, TableKind kind);

}  // namespace kerf::ui
