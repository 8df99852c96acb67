// Every table in the shared corpus, read in place: byte-exact round trip and values checked
// against the files as read by eye.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/tables/table_file.h"
#include "core/tables/tnc_table.h"
#include "tests/core/tables/corpus_files.h"

namespace kerf::tables {
namespace {

using test::corpusDir;
using test::readCorpus;

bool isTableFile(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    static const std::set<std::string> kTableExtensions = {".T", ".TAB", ".CDT", ".PR",
                                                           ".D", ".PNT", ".TCH"};
    return kTableExtensions.count(ext) > 0;
}

TEST(Corpus, EveryTableRoundTripsByteForByte) {
    int tables = 0;
    for (const auto& entry : std::filesystem::directory_iterator(corpusDir())) {
        if (!entry.is_regular_file() || !isTableFile(entry.path())) continue;
        ++tables;
        auto bytes = readWholeFile(entry.path());
        ASSERT_TRUE(bytes.ok());
        auto table = loadTable(entry.path());
        ASSERT_TRUE(table.ok()) << table.error().format();
        EXPECT_EQ(table->serialize(), *bytes) << entry.path();
        EXPECT_GT(table->rowCount(), 0u) << entry.path();
    }
    EXPECT_GE(tables, 4);
}

TEST(Corpus, OldToolTableWithDecimalCommaAndNoEnd) {
    auto table = TncTable::parse(readCorpus(test::kAamorimTool));
    ASSERT_TRUE(table.ok());
    EXPECT_EQ(table->tableName(), "TOOL");
    EXPECT_EQ(table->unit(), "MM");
    EXPECT_EQ(table->rowCount(), 100u);
    auto row = table->findRow("15");
    ASSERT_TRUE(row);
    EXPECT_EQ(table->cell(*row, *table->findColumn("NAME")), "6,0mm_JOBBER_DRI");
    EXPECT_EQ(table->number(*row, *table->findColumn("L")), 18.892);
    EXPECT_EQ(table->rowLineNumber(*row), 18u);
    // Header names CUR.TIME and DOC, but the rows end after CUR.TIME.
    EXPECT_EQ(table->cell(3, *table->findColumn("CUR.TIME")), "2");
    EXPECT_EQ(table->cell(3, *table->findColumn("DOC")), "");
}

TEST(Corpus, PalletTableTakesColumnTypesFromItsDescription) {
    auto table = TncTable::parse(readCorpus(test::kPalletMag));
    ASSERT_TRUE(table.ok());
    EXPECT_EQ(table->headerLineNumber(), 48u);
    ASSERT_EQ(table->columns().size(), 5u);
    EXPECT_EQ(table->columns()[4].name, "PROGRAM");
    EXPECT_EQ(table->columnFormat(0).kind, CellKind::Integer);
    EXPECT_EQ(table->columnFormat(1).kind, CellKind::Text);
    EXPECT_EQ(table->columnFormat(2).kind, CellKind::Integer);
    EXPECT_EQ(table->columnFormat(2).defaultValue, "+0");
    EXPECT_EQ(table->rowCount(), 7u);
    EXPECT_EQ(table->cell(0, 3), "Milling");
    EXPECT_EQ(table->cell(0, 4), "v:\\program\\4711.pm");
    EXPECT_EQ(table->number(5, 2), 0.0);  // "+0"
    EXPECT_EQ(table->cell(5, 4), "");
}

TEST(Corpus, CuttingDataTableKeepsItsStructSection) {
    auto table = TncTable::parse(readCorpus(test::kCuttingData));
    ASSERT_TRUE(table.ok());
    EXPECT_EQ(table->tableName(), "FRAES_GB");
    EXPECT_EQ(table->extension(), "CDT");
    EXPECT_EQ(table->unit(), "");
    EXPECT_EQ(table->headerLineNumber(), 114u);
    EXPECT_EQ(table->rowCount(), 117u);
    auto row = table->findRow("113");
    ASSERT_TRUE(row);
    EXPECT_EQ(table->cell(*row, 1), "Ti 99,4");  // text with a comma stays text
    EXPECT_EQ(table->cell(*row, 2), "Carbide ins.");
    EXPECT_EQ(table->number(*row, 3), 35.0);
    EXPECT_EQ(table->number(*row, 4), 0.025);
    EXPECT_EQ(table->number(*row, 6), 0.035);  // F2, beyond the end of the header line
    EXPECT_EQ(table->columnFormat(1).kind, CellKind::Text);    // WMAT TYPE = C
    EXPECT_EQ(table->columnFormat(4).kind, CellKind::Number);  // F1 TYPE = N
    EXPECT_EQ(table->columnFormat(4).defaultDecimals, 3);
}

TEST(Corpus, EditingOneCellChangesOnlyThatCell) {
    const std::string original = readCorpus(test::kCuttingData);
    auto table = TncTable::parse(original);
    ASSERT_TRUE(table.ok());
    ASSERT_FALSE(table->setNumber(*table->findRow("2"), *table->findColumn("F1"), 0.25));
    const std::string before =
        "2       St 33-1          HC-P25           100     0,200   130     0,250   ";
    const std::string after =
        "2       St 33-1          HC-P25           100     0,250   130     0,250   ";
    std::string expected = original;
    size_t at = expected.find(before);
    ASSERT_NE(at, std::string::npos);
    expected.replace(at, before.size(), after);
    EXPECT_EQ(table->serialize(), expected);
}

}  // namespace
}  // namespace kerf::tables
