#include "core/tables/tnc_table.h"

#include <limits>
#include <string>

#include <gtest/gtest.h>

namespace kerf::tables {
namespace {

// Old TNC style: decimal comma, rows end after their last value, CRLF.
const std::string kCommaTable =
    "BEGIN TEST   .TAB     MM\r\n"
    "NR   X        Y        DOC\r\n"
    "0    +1,500   -2,000   first\r\n"
    "1    +0,000   +3,250\r\n"
    "[END]\r\n";

TncTable parseOrDie(const std::string& text) {
    auto table = TncTable::parse(text, "test.tab");
    EXPECT_TRUE(table.ok()) << (table.ok() ? "" : table.error().format());
    return std::move(table).value();
}

TEST(TncTable, ReadsBeginLineColumnsAndCells) {
    TncTable table = parseOrDie(kCommaTable);
    EXPECT_EQ(table.tableName(), "TEST");
    EXPECT_EQ(table.extension(), "TAB");
    EXPECT_EQ(table.unit(), "MM");
    ASSERT_EQ(table.columns().size(), 4u);
    EXPECT_EQ(table.columns()[1].name, "X");
    EXPECT_EQ(table.columns()[1].start, 5u);
    EXPECT_EQ(table.columns()[1].width, 9u);
    EXPECT_EQ(table.columns()[3].width, 5u);  // "first" is the widest DOC
    EXPECT_EQ(table.rowCount(), 2u);
    EXPECT_EQ(table.cell(0, 1), "+1,500");
    EXPECT_EQ(table.rawCell(0, 1), "+1,500   ");
    EXPECT_EQ(table.number(0, 2), -2.0);
    EXPECT_EQ(table.number(1, 2), 3.25);
    EXPECT_EQ(table.cell(0, 3), "first");
    EXPECT_EQ(table.cell(1, 3), "");
    EXPECT_FALSE(table.number(0, 3));
    EXPECT_EQ(table.cell(7, 0), "");  // out of range is empty, not a crash
}

TEST(TncTable, FindsRowsAndColumns) {
    TncTable table = parseOrDie(kCommaTable);
    EXPECT_EQ(table.findColumn("Y"), 2u);
    EXPECT_FALSE(table.findColumn("Z"));
    EXPECT_FALSE(table.findColumn("y"));
    EXPECT_EQ(table.findRow("1"), 1u);
    EXPECT_FALSE(table.findRow("2"));
    EXPECT_EQ(table.findRowByNumber(0.0), 0u);
    EXPECT_EQ(table.headerLineNumber(), 2u);
    EXPECT_EQ(table.rowLineNumber(1), 4u);
    EXPECT_EQ(table.columnNumber(2), 15u);
}

TEST(TncTable, BeginLineVariants) {
    auto tool = parseOrDie("BEGIN TOOL.T MM Version: 'Update:110.24'\nT NAME\n[END]\n");
    EXPECT_EQ(tool.tableName(), "TOOL");
    EXPECT_EQ(tool.extension(), "T");
    EXPECT_EQ(tool.unit(), "MM");
    auto cdt = parseOrDie("BEGIN FRAES_GB.CDT \nNR A\n[END]\n");
    EXPECT_EQ(cdt.extension(), "CDT");
    EXPECT_EQ(cdt.unit(), "");
    auto inch = parseOrDie("BEGIN P  .PNT   INCH\nNR X\n");
    EXPECT_EQ(inch.tableName(), "P");
    EXPECT_EQ(inch.unit(), "INCH");
}

TEST(TncTable, SerializesUnmodifiedTablesByteForByte) {
    const std::string samples[] = {
        kCommaTable,
        // No [END], no final newline, trailing spaces.
        "BEGIN B.TAB\nNR  VALUE \n0   1  \n1   2",
        // Mixed endings, blank lines, a description block, cp1252 bytes, text after [END].
        "BEGIN C.TAB INCH extra words\r\n\r\n#STRUCTBEGIN\r\n  NAME = A\r\n  TYPE = N\r\n"
        "  DEC = 2\r\n#STRUCTEND\r\nNR A     DOC\n0  1.00  K\xe4se\r\n\n1  2.50  \xbfQu\xe9?\r\n"
        "[END]\r\ntrailing junk\r\n",
        // Lone carriage returns are content, not line ends.
        "BEGIN D.TAB MM\rNR X\n0 1\r\r\n",
    };
    for (const std::string& text : samples) {
        auto table = TncTable::parse(text);
        ASSERT_TRUE(table.ok()) << text;
        EXPECT_EQ(table->serialize(), text);
    }
}

TEST(TncTable, KeepsDescriptionBlocksAndBlankLinesOutOfTheRows) {
    TncTable table = parseOrDie(
        "BEGIN C.TAB INCH\r\n\r\n#STRUCTBEGIN\r\n  NAME = A\r\n  TYPE = N\r\n  DEC = 2\r\n"
        "#STRUCTEND\r\nNR A     DOC\n0  1.00  K\xe4se\r\n\n1  2.50  \xbfQu\xe9?\r\n[END]\r\n");
    EXPECT_EQ(table.headerLineNumber(), 8u);
    ASSERT_EQ(table.rowCount(), 2u);
    EXPECT_EQ(table.rowLineNumber(1), 11u);
    EXPECT_EQ(table.cell(0, 2), "K\xe4se");
    EXPECT_EQ(table.columnFormat(1).kind, CellKind::Number);
    EXPECT_EQ(table.columnFormat(1).defaultDecimals, 2);
    EXPECT_EQ(table.columnFormat(2).kind, CellKind::Unknown);
    auto error = table.setCell(0, 1, "abc");
    ASSERT_TRUE(error);
    EXPECT_EQ(error->line, 9u);
    EXPECT_EQ(error->column, 4u);
}

TEST(TncTable, SetNumberKeepsTheCellStyle) {
    TncTable table = parseOrDie(kCommaTable);
    ASSERT_FALSE(table.setNumber(1, 1, 12.5));
    EXPECT_EQ(table.serialize(),
              "BEGIN TEST   .TAB     MM\r\n"
              "NR   X        Y        DOC\r\n"
              "0    +1,500   -2,000   first\r\n"
              "1    +12,500  +3,250\r\n"
              "[END]\r\n");
    // More decimals than the cell had when the value needs them; the sign style of the column.
    ASSERT_FALSE(table.setNumber(0, 2, 0.0625));
    EXPECT_EQ(table.cell(0, 2), "+0,0625");
}

TEST(TncTable, SetCellRewritesOnlyThatCell) {
    TncTable table = parseOrDie(kCommaTable);
    ASSERT_FALSE(table.setCell(1, 3, "second row"));  // the last column may grow
    ASSERT_FALSE(table.setCell(0, 2, ""));
    EXPECT_EQ(table.serialize(),
              "BEGIN TEST   .TAB     MM\r\n"
              "NR   X        Y        DOC\r\n"
              "0    +1,500            first\r\n"
              "1    +0,000   +3,250   second row\r\n"
              "[END]\r\n");
}

TEST(TncTable, SetCellTruncatesTextToTheColumn) {
    TncTable table = parseOrDie(kCommaTable);
    ASSERT_FALSE(table.setCell(0, 0, "123456"));
    EXPECT_EQ(table.cell(0, 0), "12345");
    EXPECT_EQ(table.cell(0, 1), "+1,500");
}

TEST(TncTable, RefusesBadEdits) {
    TncTable table = parseOrDie(kCommaTable);
    auto tooWide = table.setNumber(0, 1, 123456789.0);
    ASSERT_TRUE(tooWide);
    EXPECT_EQ(tooWide->line, 3u);
    EXPECT_EQ(tooWide->column, 6u);
    EXPECT_TRUE(table.setCell(0, 3, "two\nlines"));
    EXPECT_TRUE(table.setCell(5, 0, "x"));
    EXPECT_TRUE(table.setNumber(0, 1, std::numeric_limits<double>::infinity()));
    EXPECT_TRUE(table.removeRow(2));
    EXPECT_FALSE(table.insertRow(3, "9").ok());
    EXPECT_EQ(table.serialize(), kCommaTable);
}

TEST(TncTable, InsertsAndRemovesRows) {
    TncTable table = parseOrDie(kCommaTable);
    auto appended = table.appendRow("2");
    ASSERT_TRUE(appended.ok());
    EXPECT_EQ(*appended, 2u);
    auto inserted = table.insertRow(0, "7");
    ASSERT_TRUE(inserted.ok());
    EXPECT_EQ(table.serialize(),
              "BEGIN TEST   .TAB     MM\r\n"
              "NR   X        Y        DOC\r\n"
              "7\r\n"
              "0    +1,500   -2,000   first\r\n"
              "1    +0,000   +3,250\r\n"
              "2\r\n"
              "[END]\r\n");
    ASSERT_FALSE(table.setNumber(3, 1, 4.0));  // style from the column: "+4,000"
    EXPECT_EQ(table.cell(3, 1), "+4,000");
    ASSERT_FALSE(table.removeRow(0));
    ASSERT_FALSE(table.removeRow(2));
    EXPECT_EQ(table.serialize(), kCommaTable);
}

TEST(TncTable, KeepsAMissingFinalNewlineMissing) {
    const std::string text = "BEGIN B.TAB\nNR  VALUE \n0   1  \n1   2";
    TncTable table = parseOrDie(text);
    ASSERT_TRUE(table.appendRow("2").ok());
    EXPECT_EQ(table.serialize(), "BEGIN B.TAB\nNR  VALUE \n0   1  \n1   2\n2");
    ASSERT_FALSE(table.removeRow(2));
    EXPECT_EQ(table.serialize(), text);
    ASSERT_FALSE(table.setNumber(1, 1, 2.5));
    EXPECT_EQ(table.serialize(), "BEGIN B.TAB\nNR  VALUE \n0   1  \n1   2.5");
}

TEST(TncTable, PadsNewRowsWhenTheTableDoes) {
    TncTable table = parseOrDie("BEGIN P.TAB MM\nNR  X     Y     \n0   +1    +2    \n[END]\n");
    ASSERT_TRUE(table.appendRow("1").ok());
    EXPECT_EQ(table.serialize(), "BEGIN P.TAB MM\nNR  X     Y     \n0   +1    +2    \n1" +
                                     std::string(15, ' ') + "\n[END]\n");
}

TEST(TncTable, AppendsAColumnToAPaddedTable) {
    // Y ends at byte 16 with a space before it: the new column starts there, and the padded
    // header and rows are padded to its width too.
    TncTable table = parseOrDie("BEGIN P.TAB MM\nNR  X     Y     \n0   +1    +2    \n[END]\n");
    ASSERT_FALSE(table.appendColumn("Z", 6, ColumnFormat{}));
    EXPECT_EQ(table.serialize(), "BEGIN P.TAB MM\nNR  X     Y     Z     \n0   +1    +2    " +
                                     std::string(6, ' ') + "\n[END]\n");
    ASSERT_FALSE(table.setCell(0, 3, "+3"));
    EXPECT_EQ(table.serialize(),
              "BEGIN P.TAB MM\nNR  X     Y     Z     \n0   +1    +2    +3    \n[END]\n");
    EXPECT_EQ(table.cell(0, 2), "+2");
}

TEST(TncTable, AppendsAColumnOneSpaceAfterTheWidestCellOfAnUnpaddedTable) {
    // DOC (byte 23) is open-ended and "first" fills it up to byte 28: SPC starts at 29. The
    // rows end after their last value and stay so; the CRLF endings are kept.
    TncTable table = parseOrDie(kCommaTable);
    ASSERT_FALSE(table.appendColumn("SPC", 8, ColumnFormat{}));
    ASSERT_EQ(table.columns().back().start, 29u);
    EXPECT_EQ(table.columns()[3].width, 6u);
    ASSERT_FALSE(table.setCell(0, 4, "7"));
    EXPECT_EQ(table.serialize(),
              "BEGIN TEST   .TAB     MM\r\n"
              "NR   X        Y        DOC   SPC\r\n"
              "0    +1,500   -2,000   first 7\r\n"
              "1    +0,000   +3,250\r\n"
              "[END]\r\n");
    EXPECT_EQ(table.cell(0, 3), "first");
    EXPECT_TRUE(table.appendColumn("SPC", 8, ColumnFormat{}));  // already there
    EXPECT_TRUE(table.appendColumn("A B", 8, ColumnFormat{}));
}

TEST(TncTable, NewRowsTakeDeclaredDefaultsInTheColumnStyle) {
    TncTable table = parseOrDie("BEGIN P.TAB MM\nNR  X       NOTE\n0   +1,50   a\n[END]\n");
    ColumnFormat number;
    number.kind = CellKind::Number;
    number.defaultValue = "0";
    table.setColumnFormat("X", number);
    ColumnFormat text;
    text.kind = CellKind::Text;
    text.defaultValue = "new";
    table.setColumnFormat("NOTE", text);
    ASSERT_TRUE(table.appendRow("1").ok());
    EXPECT_EQ(table.cell(1, 1), "+0,00");
    EXPECT_EQ(table.cell(1, 2), "new");
    EXPECT_TRUE(table.setNumber(1, 2, 3.0));  // declared text
}

}  // namespace
}  // namespace kerf::tables
