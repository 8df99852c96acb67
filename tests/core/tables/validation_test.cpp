#include <string>

#include <gtest/gtest.h>

#include "core/tables/datum_table.h"
#include "core/tables/point_table.h"
#include "core/tables/preset_table.h"
#include "core/tables/table_validation.h"
#include "core/tables/tool_table.h"

namespace kerf::tables {
namespace {

void expectError(const Diagnostic& error, uint32_t line, uint32_t column,
                 const std::string& message) {
    EXPECT_EQ(error.severity, Severity::Error);
    EXPECT_EQ(error.code, "table");
    EXPECT_EQ(error.file, "TOOL.T");
    EXPECT_EQ(error.line, line);
    EXPECT_EQ(error.column, column);
    EXPECT_EQ(error.message(), message);
}

Diagnostic toolError(const std::string& text) {
    auto tools = ToolTable::parse(text, "TOOL.T");
    EXPECT_FALSE(tools.ok());
    return tools.ok() ? Diagnostic{} : tools.error();
}

TEST(Validation, MissingOrBrokenBeginLine) {
    expectError(toolError("TOOL.T MM\nT NAME\n[END]\n"), 1, 1,
                "the table does not start with a BEGIN line");
    expectError(toolError(""), 1, 1, "the table does not start with a BEGIN line");
    expectError(toolError("BEGINTOOL.T\n"), 1, 1, "the table does not start with a BEGIN line");
    expectError(toolError("BEGIN TOOL MM\nT NAME\n"), 1, 12, "the BEGIN line gives no file type");
    expectError(toolError("BEGIN \nT NAME\n"), 1, 7, "the BEGIN line names no table");
}

TEST(Validation, MissingColumnHeader) {
    expectError(toolError("BEGIN TOOL.T MM\n[END]\n"), 2, 1, "the table has no column header line");
    expectError(toolError("BEGIN TOOL.T MM\n"), 2, 1, "the table has no column header line");
    expectError(toolError("BEGIN TOOL.T MM\n\n#STRUCTBEGIN\nNAME = T\n"), 5, 1,
                "the table has no column header line");
}

TEST(Validation, NonNumericValueInNumericColumn) {
    const std::string text =
        "BEGIN TOOL.T MM\n"
        "T    NAME     L        R\n"
        "1    DRILL    +5,000   +2,000\n"
        "2    MILL     +5,0x0   +1,000\n"
        "[END]\n";
    Diagnostic error = toolError(text);
    expectError(error, 4, 15, "column L needs a number, not \"+5,0x0\"");
    EXPECT_EQ(error.args, (std::vector<std::string>{"L", "+5,0x0"}));
    EXPECT_EQ(error.format(), "TOOL.T:4:15: error: column L needs a number, not \"+5,0x0\"");
}

TEST(Validation, ReportsEveryBadCell) {
    auto table = TncTable::parse(
        "BEGIN TOOL.T MM\nT    L        R\n1    x        +1\n2    +1       y\n[END]\n", "TOOL.T");
    ASSERT_TRUE(table.ok());
    ColumnFormat number;
    number.kind = CellKind::Number;
    table->setColumnFormat("L", number);
    table->setColumnFormat("R", number);
    DiagnosticList errors = checkNumericCells(*table);
    ASSERT_EQ(errors.size(), 2u);
    expectError(errors[0], 3, 6, "column L needs a number, not \"x\"");
    expectError(errors[1], 4, 15, "column R needs a number, not \"y\"");
}

TEST(Validation, MissingKeyColumn) {
    expectError(toolError("BEGIN TOOL.T MM\nNR   NAME\n0    A\n[END]\n"), 2, 1,
                "the table has no column T");
    auto datums = DatumTable::parse("BEGIN D.D MM\n\nX    Y\n+1   +2\n", "TOOL.T");
    ASSERT_FALSE(datums.ok());
    expectError(datums.error(), 3, 1, "the table has no column D");
}

TEST(Validation, DuplicateAndBadToolNumbers) {
    expectError(toolError("BEGIN TOOL.T MM\nT    NAME\n1    A\n2    B\n1    C\n[END]\n"), 5, 1,
                "T 1 appears twice (first in line 3)");
    expectError(toolError("BEGIN TOOL.T MM\nNAME T\nA    \n[END]\n"), 3, 6,
                "the key column T is empty");
    expectError(toolError("BEGIN TOOL.T MM\nNAME T\nA    x1\n[END]\n"), 3, 6,
                "column T needs a whole number >= 0, not \"x1\"");
    expectError(toolError("BEGIN TOOL.T MM\nT    NAME\n-3   A\n[END]\n"), 3, 1,
                "column T needs a whole number >= 0, not \"-3\"");
}

TEST(Validation, ToolSpecificColumns) {
    expectError(toolError("BEGIN TOOL.T MM\nT    TL CUT\n1    X  2\n[END]\n"), 3, 6,
                "column TL needs L, 1, 0 or nothing, not \"X\"");
    expectError(toolError("BEGIN TOOL.T MM\nT    TL CUT\n1    L  2.5\n[END]\n"), 3, 9,
                "column CUT needs a whole number, not \"2.5\"");
}

TEST(Validation, KeyedTables) {
    auto presets = PresetTable::parse("BEGIN PRESET.PR MM\nNR   X\n0    12..5\n[END]\n", "TOOL.T");
    ASSERT_FALSE(presets.ok());
    expectError(presets.error(), 3, 6, "column X needs a number, not \"12..5\"");

    auto presetTwice =
        PresetTable::parse("BEGIN PRESET.PR MM\nNR   X\n0    +1\n0    +2\n", "TOOL.T");
    ASSERT_FALSE(presetTwice.ok());
    expectError(presetTwice.error(), 4, 1, "NR 0 appears twice (first in line 3)");

    auto points = PointTable::parse(
        "BEGIN P.PNT MM\nNR  X    FADE CLEAR\n0   +1   Y    maybe\n[END]\n", "TOOL.T");
    ASSERT_FALSE(points.ok());
    expectError(points.error(), 3, 15, "column CLEAR needs Y or nothing, not \"maybe\"");

    auto indexed = PointTable::parse("BEGIN P.PNT MM\nNR  X\n1.5 +1\n[END]\n", "TOOL.T");
    ASSERT_FALSE(indexed.ok());
    expectError(indexed.error(), 3, 1, "column NR needs a whole number >= 0, not \"1.5\"");
}

}  // namespace
}  // namespace kerf::tables
