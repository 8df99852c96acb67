#include "core/tables/table_file.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/tables/tool_table.h"
#include "tests/core/tables/corpus_files.h"

namespace kerf::tables {
namespace {

namespace fs = std::filesystem;

int entriesIn(const fs::path& dir) {
    int count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir))
        ++count;
    return count;
}

TEST(TableFile, SavesTheSameBytesAtomically) {
    fs::path dir = test::freshTempDir("table_file");
    fs::path path = dir / "TEST.TAB";
    const std::string text = "BEGIN TEST.TAB MM\r\nNR   X\r\n0    +1,000\r\n[END]";
    ASSERT_FALSE(writeFileAtomically(path, text));
    auto table = loadTable(path);
    ASSERT_TRUE(table.ok());
    EXPECT_EQ(table->fileName(), path.string());
    ASSERT_FALSE(table->setNumber(0, 1, 2.5));
    ASSERT_FALSE(saveTable(*table, path));
    EXPECT_EQ(readWholeFile(path).value(), "BEGIN TEST.TAB MM\r\nNR   X\r\n0    +2,500\r\n[END]");
    EXPECT_EQ(entriesIn(dir), 1);  // no temporary file left behind
    fs::remove_all(dir);
}

TEST(TableFile, ToolTableSurvivesSaveAndLoad) {
    fs::path dir = test::freshTempDir("tool_save");
    fs::path path = dir / "TOOL.T";
    auto tools = ToolTable::load(test::corpusFile(test::kPyLsv2Tool));
    ASSERT_TRUE(tools.ok());
    ASSERT_FALSE(tools->setNumber(1, "DL", -0.02));
    ASSERT_FALSE(tools->save(path));
    auto again = ToolTable::load(path);
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_DOUBLE_EQ(again->byNumber(1)->deltaLength, -0.02);
    EXPECT_EQ(again->serialize(), tools->serialize());
    EXPECT_EQ(entriesIn(dir), 1);
    fs::remove_all(dir);
}

TEST(TableFile, ReportsIoErrors) {
    auto missing = loadTable("/nonexistent-kerf-dir/TOOL.T");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, "io");
    auto table = TncTable::parse("BEGIN T.TAB\nNR\n");
    ASSERT_TRUE(table.ok());
    auto error = saveTable(*table, "/nonexistent-kerf-dir/T.TAB");
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "io");
}

TEST(TableFile, DiagnosticsNameTheFile) {
    fs::path dir = test::freshTempDir("bad_tool");
    fs::path path = dir / "TOOL.T";
    ASSERT_FALSE(writeFileAtomically(path, "BEGIN TOOL.T MM\nT    L\n1    abc\n[END]\n"));
    auto tools = ToolTable::load(path);
    ASSERT_FALSE(tools.ok());
    EXPECT_EQ(tools.error().format(),
              path.string() + ":3:6: error: column L needs a number, not \"abc\"");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kerf::tables
