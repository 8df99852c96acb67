#include "core/tables/free_table.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/core/tables/corpus_files.h"

namespace kerf::tables {
namespace {

FreeTable fromText(const std::string& text) {
    auto table = TncTable::parse(text, "test.tab");
    EXPECT_TRUE(table.ok());
    auto free = FreeTable::fromTable(std::move(table).value());
    EXPECT_TRUE(free.ok());
    return std::move(free).value();
}

TEST(FreeTable, ReadsNumbersByRowAndColumnNames) {
    auto pallets = FreeTable::open(test::corpusFile(test::kPalletMag));
    ASSERT_TRUE(pallets.ok()) << pallets.error().format();
    EXPECT_EQ(pallets->read(0, "PAL_NR").value(), std::vector<double>{90.0});
    EXPECT_EQ(pallets->read(5, "KEY,PAL_NR").value(), (std::vector<double>{5.0, 0.0}));
    EXPECT_EQ(pallets->read(2, " PAL_NR , KEY ").value(), (std::vector<double>{47.0, 2.0}));

    auto cutting = FreeTable::open(test::corpusFile(test::kCuttingData));
    ASSERT_TRUE(cutting.ok());
    EXPECT_EQ(cutting->read(2, "Vc1,F1,Vc2,F2").value(),
              (std::vector<double>{100.0, 0.2, 130.0, 0.25}));
    EXPECT_EQ(cutting->read(116, "F1").value(), std::vector<double>{0.2});
}

TEST(FreeTable, ReadErrorsNameThePlace) {
    auto pallets = FreeTable::open(test::corpusFile(test::kPalletMag));
    ASSERT_TRUE(pallets.ok());
    auto text = pallets->read(0, "NAME");
    ASSERT_FALSE(text.ok());
    EXPECT_EQ(text.error().line, 49u);
    EXPECT_EQ(text.error().column, 9u);
    EXPECT_EQ(text.error().message(), "column NAME needs a number, not \"Machine\"");
    auto empty = pallets->read(6, "PROGRAM");
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().line, 55u);
    EXPECT_EQ(empty.error().column, 40u);
    auto noRow = pallets->read(7, "PAL_NR");
    ASSERT_FALSE(noRow.ok());
    EXPECT_EQ(noRow.error().message(), "the table has no row 7");
    auto noColumn = pallets->read(0, "PAL_NR,SLOT");
    ASSERT_FALSE(noColumn.ok());
    EXPECT_EQ(noColumn.error().message(), "the table has no column \"SLOT\"");
    EXPECT_EQ(noColumn.error().line, 48u);
}

TEST(FreeTable, WritesNumbersIntoExistingRowsOnly) {
    const std::string original = test::readCorpus(test::kPalletMag);
    auto table = TncTable::parse(original);
    ASSERT_TRUE(table.ok());
    auto pallets = FreeTable::fromTable(std::move(*table)).value();
    const double value = 48.0;
    ASSERT_FALSE(pallets.write(2, "PAL_NR", {&value, 1}));
    EXPECT_TRUE(pallets.modified());
    EXPECT_EQ(pallets.read(2, "PAL_NR").value(), std::vector<double>{48.0});
    std::string expected = original;
    const std::string before = "2       Transport      47      Busy";
    expected.replace(expected.find(before), before.size(), "2       Transport      48      Busy");
    EXPECT_EQ(pallets.table().serialize(), expected);

    auto missing = pallets.write(7, "PAL_NR", {&value, 1});
    ASSERT_TRUE(missing);
    EXPECT_EQ(missing->message(), "the table has no row 7");
    EXPECT_EQ(pallets.table().rowCount(), 7u);
    EXPECT_TRUE(pallets.write(2, "STATUS", {&value, 1}));   // declared TEXT
    EXPECT_TRUE(pallets.write(5, "PROGRAM", {&value, 1}));  // declared TEXT, though empty
    const double two[] = {1.0, 2.0};
    EXPECT_TRUE(pallets.write(2, "PAL_NR", two));  // two values, one column
    // All or nothing: PAL_NR is not written when NAME refuses.
    EXPECT_TRUE(pallets.write(2, "PAL_NR,NAME", two));
    EXPECT_EQ(pallets.table().serialize(), expected);
}

TEST(FreeTable, WritesInTheStyleOfTheCell) {
    auto cutting = FreeTable::open(test::corpusFile(test::kCuttingData));
    ASSERT_TRUE(cutting.ok());
    const double values[] = {0.0715, 60.0};
    ASSERT_FALSE(cutting->write(114, "F2,Vc2", values));
    EXPECT_EQ(cutting->table().cell(114, 6), "0,0715");
    EXPECT_EQ(cutting->table().cell(114, 5), "60");

    FreeTable parts =
        fromText("BEGIN 90304_DE.TAB MM\nNR    Stueck    Name\n0     +5        Teil A\n[END]\n");
    EXPECT_EQ(parts.read(0, "Stueck").value(), std::vector<double>{5.0});
    const double six = 6.0;
    ASSERT_FALSE(parts.write(0, "Stueck", {&six, 1}));
    EXPECT_EQ(parts.table().serialize(),
              "BEGIN 90304_DE.TAB MM\nNR    Stueck    Name\n0     +6        Teil A\n[END]\n");
    auto overText = parts.write(0, "Name", {&six, 1});
    ASSERT_TRUE(overText);
    EXPECT_EQ(overText->column, 17u);
}

TEST(FreeTable, SavesToTheFileItWasOpenedFrom) {
    auto dir = test::freshTempDir("free_table");
    auto path = dir / "PALLETMAG.TAB";
    ASSERT_FALSE(writeFileAtomically(path, test::readCorpus(test::kPalletMag)));
    auto pallets = FreeTable::open(path);
    ASSERT_TRUE(pallets.ok());
    EXPECT_FALSE(pallets->modified());
    const double value = 12.0;
    ASSERT_FALSE(pallets->write(4, "PAL_NR", {&value, 1}));
    ASSERT_FALSE(pallets->save());
    auto again = FreeTable::open(path);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->read(4, "PAL_NR").value(), std::vector<double>{12.0});
    EXPECT_EQ(again->table().serialize(), pallets->table().serialize());
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kerf::tables
