#include "core/tables/tool_table.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/core/tables/corpus_files.h"

namespace kerf::tables {
namespace {

using test::readCorpus;

ToolTable loadCorpusTools(const std::string& name) {
    auto tools = ToolTable::load(test::corpusFile(name));
    EXPECT_TRUE(tools.ok()) << (tools.ok() ? "" : tools.error().format());
    return std::move(tools).value();
}

TEST(ToolTable, ReadsTheOldCommaTable) {
    ToolTable tools = loadCorpusTools(test::kAamorimTool);
    EXPECT_EQ(tools.tools().size(), 100u);
    const ToolData* five = tools.byNumber(5);
    ASSERT_NE(five, nullptr);
    EXPECT_EQ(five->name, "14MM_CRB_4FL_32_");
    EXPECT_DOUBLE_EQ(five->length, -4.686);
    EXPECT_EQ(five->radius, 0.0);
    EXPECT_EQ(five->radius2, 0.0);  // no R2 column
    EXPECT_FALSE(five->locked);

    const ToolData* three = tools.byNumber(3);
    ASSERT_NE(three, nullptr);
    EXPECT_EQ(three->name, "12MM_CRB_2FL_25_");
    EXPECT_DOUBLE_EQ(three->deltaRadius, -0.425);
    EXPECT_EQ(three->currentTimeMinutes, 2.0);  // older column name CUR.TIME

    const ToolData* sixteen = tools.byNumber(16);
    ASSERT_NE(sixteen, nullptr);
    EXPECT_EQ(sixteen->name, "20,0mm_JOBBER_DR");
    EXPECT_DOUBLE_EQ(sixteen->length, 18.892);
    EXPECT_EQ(sixteen->radius, 10.0);
    EXPECT_EQ(sixteen->row, 16u);

    EXPECT_EQ(tools.byNumber(2)->radius, 5.0);
    EXPECT_EQ(tools.byNumber(4)->name, "");
    EXPECT_EQ(tools.byNumber(100), nullptr);
    EXPECT_EQ(tools.numberCell(16, "R"), 10.0);
    EXPECT_FALSE(tools.numberCell(16, "R2"));
    EXPECT_FALSE(tools.numberCell(100, "R"));
}

TEST(ToolTable, FindsByNameCaseSensitively) {
    ToolTable tools = loadCorpusTools(test::kAamorimTool);
    // Tools 1 and 5 share this name; tool 1 comes first and is not locked.
    ASSERT_NE(tools.byName("14MM_CRB_4FL_32_"), nullptr);
    EXPECT_EQ(tools.byName("14MM_CRB_4FL_32_")->number, 1);
    EXPECT_EQ(tools.byName("14mm_crb_4fl_32_"), nullptr);
    EXPECT_EQ(tools.byName("12MM/3mm_CRB_90D")->number, 17);
    EXPECT_EQ(tools.byName(""), nullptr);
}

TEST(ToolTable, ReadsTheTnc320Table) {
    ToolTable tools = loadCorpusTools(test::kPyLsv2Tool);
    EXPECT_EQ(tools.tools().size(), 7u);
    EXPECT_EQ(tools.byNumber(0)->name, "NULLWERKZEUG");

    const ToolData* rough = tools.byNumber(1);
    ASSERT_NE(rough, nullptr);
    EXPECT_EQ(rough->name, "MILL_D2_ROUGH");
    EXPECT_EQ(rough->length, 30.0);
    EXPECT_EQ(rough->radius, 1.0);
    EXPECT_EQ(rough->cuttingLength, 20.0);
    EXPECT_EQ(rough->plungeAngle, 6.0);
    EXPECT_EQ(rough->cutterCount, 2);
    EXPECT_EQ(rough->pointAngle, 0.0);
    EXPECT_EQ(rough->pitch, 0.0);

    const ToolData* torus = tools.byNumber(88);
    ASSERT_NE(torus, nullptr);
    EXPECT_EQ(torus->name, "TORUS_MILL_D3_05");
    EXPECT_EQ(torus->length, 60.0);
    EXPECT_EQ(torus->radius, 1.5);
    EXPECT_EQ(torus->radius2, 0.5);
    EXPECT_EQ(torus->cuttingLength, 40.0);

    const ToolData* probe = tools.byNumber(500);
    ASSERT_NE(probe, nullptr);
    EXPECT_EQ(probe->name, "TOUCH_PROBE");
    EXPECT_EQ(probe->length, 200.0);
    EXPECT_EQ(probe->radius, 2.0);
    EXPECT_EQ(tools.numberCell(500, "TYP"), 21.0);
    EXPECT_EQ(tools.numberCell(500, "TP_NO"), 1.0);
    EXPECT_EQ(tools.numberCell(1, "DIRECT"), -1.0);
    EXPECT_FALSE(tools.numberCell(1, "NAME"));
    EXPECT_FALSE(tools.numberCell(1, "AFC"));  // empty
    const TncTable& table = tools.table();
    EXPECT_EQ(table.cell(probe->row, *table.findColumn("KINEMATIC")), "ts_444_s69.cfg");
}

TEST(ToolTable, SkipsLockedToolsWhenSearchingByName) {
    auto tools = ToolTable::parse(
        "BEGIN TOOL.T MM\n"
        "T    NAME     L        R        TL\n"
        "1    MILL     +50      +5       L\n"
        "2    MILL     +51      +5\n"
        "3    mill     +52      +4\n"
        "4    DRILL    +60      +2       L\n"
        "5    DRILL    +61      +2       1\n"
        "[END]\n");
    ASSERT_TRUE(tools.ok()) << tools.error().format();
    EXPECT_TRUE(tools->byNumber(1)->locked);
    EXPECT_FALSE(tools->byNumber(2)->locked);
    EXPECT_TRUE(tools->byNumber(5)->locked);
    EXPECT_EQ(tools->byName("MILL")->number, 2);
    EXPECT_EQ(tools->byName("mill")->number, 3);
    EXPECT_EQ(tools->byName("DRILL")->number, 4);  // all locked: the first, for the error
    EXPECT_EQ(tools->byName("TAP"), nullptr);
}

TEST(ToolTable, ReadsIndexedTools) {
    auto tools = ToolTable::parse(
        "BEGIN TOOL.T MM\nT       NAME   L\n5       A      +10\n5.1     B      +11\n[END]\n");
    ASSERT_TRUE(tools.ok()) << tools.error().format();
    EXPECT_EQ(tools->byNumber(5)->name, "A");
    ASSERT_NE(tools->byNumber(5, 1), nullptr);
    EXPECT_EQ(tools->byNumber(5, 1)->length, 11.0);
}

TEST(ToolTable, EditsOneCellInTheFileStyle) {
    const std::string original = readCorpus(test::kAamorimTool);
    auto tools = ToolTable::parse(original, "TOOL.T");
    ASSERT_TRUE(tools.ok());
    ASSERT_FALSE(tools->setNumber(5, "L", -4.7));
    ASSERT_FALSE(tools->setText(4, "NAME", "NEW_TOOL"));
    EXPECT_DOUBLE_EQ(tools->byNumber(5)->length, -4.7);
    EXPECT_EQ(tools->byNumber(4)->name, "NEW_TOOL");

    std::string expected = original;
    const std::string tool4 =
        "4                     +0,000     +0,000     +0,000  +0,000         0     0     9\n";
    const std::string tool5 =
        "5    14MM_CRB_4FL_32_ -4,686     +0,000     +0,000  +0,000         0     0     0\n";
    expected.replace(
        expected.find(tool4), tool4.size(),
        "4    NEW_TOOL         +0,000     +0,000     +0,000  +0,000         0     0     9\n");
    expected.replace(
        expected.find(tool5), tool5.size(),
        "5    14MM_CRB_4FL_32_ -4,700     +0,000     +0,000  +0,000         0     0     0\n");
    EXPECT_EQ(tools->serialize(), expected);
}

TEST(ToolTable, EditsKeepTheNewStyle) {
    const std::string original = readCorpus(test::kPyLsv2Tool);
    auto tools = ToolTable::parse(original);
    ASSERT_TRUE(tools.ok());
    ASSERT_FALSE(tools->setNumber(87, "R2", 0.75));
    EXPECT_EQ(tools->byNumber(87)->radius2, 0.75);
    std::string expected = original;
    const std::string before =
        "87      TORUS_MILL_D2_05                +60         +1          +0.5        +0 ";
    const std::string after =
        "87      TORUS_MILL_D2_05                +60         +1          +0.75       +0 ";
    expected.replace(expected.find(before), before.size(), after);
    EXPECT_EQ(tools->serialize(), expected);
}

TEST(ToolTable, AddsToolsInOrderWithDefaults) {
    auto tools = ToolTable::parse(readCorpus(test::kAamorimTool));
    ASSERT_TRUE(tools.ok());
    const std::string original = tools->serialize();
    ASSERT_FALSE(tools->addTool(100));
    EXPECT_EQ(
        tools->serialize(),
        original + "100                   +0,000     +0,000     +0,000  +0,000         0     0\n");
    EXPECT_EQ(tools->byNumber(100)->row, 100u);
    EXPECT_TRUE(tools->addTool(5));   // exists
    EXPECT_TRUE(tools->addTool(-1));  // negative

    auto modern = ToolTable::parse(readCorpus(test::kPyLsv2Tool));
    ASSERT_TRUE(modern.ok());
    ASSERT_FALSE(modern->addTool(2));
    const ToolData* two = modern->byNumber(2);
    ASSERT_NE(two, nullptr);
    EXPECT_EQ(two->row, 2u);  // between tools 1 and 57
    const TncTable& table = modern->table();
    EXPECT_EQ(table.cell(2, *table.findColumn("L")), "+0");
    EXPECT_EQ(table.cell(2, *table.findColumn("DIRECT")), "-1");
    EXPECT_EQ(table.cell(2, *table.findColumn("PLC")), "%00000000");
    EXPECT_EQ(table.cell(2, *table.findColumn("R-OFFS")), "");           // empty in every row
    EXPECT_EQ(table.rawCell(2, table.columns().size() - 1).size(), 8u);  // padded like the rest
    ASSERT_FALSE(modern->removeTool(2));
    EXPECT_EQ(modern->serialize(), readCorpus(test::kPyLsv2Tool));
}

TEST(ToolTable, FailedEditsChangeNothing) {
    auto tools = ToolTable::parse(readCorpus(test::kAamorimTool));
    ASSERT_TRUE(tools.ok());
    const std::string original = tools->serialize();
    auto notNumber = tools->setText(5, "L", "abc");
    ASSERT_TRUE(notNumber);
    EXPECT_EQ(notNumber->line, 8u);
    EXPECT_EQ(notNumber->column, 23u);
    EXPECT_TRUE(tools->setNumber(999, "L", 1.0));
    EXPECT_TRUE(tools->setNumber(5, "NOPE", 1.0));
    EXPECT_TRUE(tools->setNumber(5, "NAME", 1.0));
    auto duplicate = tools->setText(5, "T", "3");
    ASSERT_TRUE(duplicate);
    EXPECT_NE(duplicate->message().find("twice"), std::string::npos);
    EXPECT_TRUE(tools->removeTool(999));
    EXPECT_EQ(tools->serialize(), original);
    EXPECT_DOUBLE_EQ(tools->byNumber(5)->length, -4.686);
}

TEST(ToolTable, DefaultTableHasTheTnc320Columns) {
    const std::string text = ToolTable::createDefault();
    auto tools = ToolTable::parse(text);
    ASSERT_TRUE(tools.ok()) << tools.error().format();
    EXPECT_EQ(tools->serialize(), text);
    EXPECT_EQ(text.substr(0, 16), "BEGIN TOOL.T MM\n");
    EXPECT_EQ(text.substr(text.size() - 6), "[END]\n");

    const std::vector<std::string> expected = {
        "T",        "NAME",   "L",      "R",     "R2",        "DL",     "DR",      "DR2",
        "TL",       "RT",     "TIME1",  "TIME2", "CUR_TIME",  "TYP",    "DOC",     "PLC",
        "LCUTS",    "ANGLE",  "CUT",    "LTOL",  "RTOL",      "R2TOL",  "DIRECT",  "R-OFFS",
        "L-OFFS",   "LBREAK", "RBREAK", "NMAX",  "LIFTOFF",   "TP_NO",  "T-ANGLE", "PITCH",
        "LAST_USE", "PTYP",   "AFC",    "ACC",   "KINEMATIC", "OVRTIME"};
    std::vector<std::string> names;
    for (const TableColumn& column : tools->table().columns())
        names.push_back(column.name);
    EXPECT_EQ(names, expected);

    ASSERT_EQ(tools->tools().size(), 1u);
    const ToolData* zero = tools->byNumber(0);
    ASSERT_NE(zero, nullptr);
    EXPECT_EQ(zero->length, 0.0);
    EXPECT_FALSE(zero->locked);
    EXPECT_EQ(tools->table().cell(0, *tools->table().findColumn("L")), "+0");

    // Same positions as the TOOL.T a TNC wrote, for the columns both have.
    auto real = TncTable::parse(readCorpus(test::kPyLsv2Tool));
    ASSERT_TRUE(real.ok());
    for (const char* name : {"NAME", "L", "DR2", "TIME1", "DOC", "CUT", "NMAX", "PITCH"}) {
        const TncTable& table = tools->table();
        EXPECT_EQ(table.columns()[*table.findColumn(name)].start,
                  real->columns()[*real->findColumn(name)].start)
            << name;
    }
    EXPECT_EQ(ToolTable::createDefault(TableUnit::Inch).substr(0, 18), "BEGIN TOOL.T INCH\n");
}

// CUT and TP_NO are read as int: a number beyond int (a last column may be as long as the line)
// was undefined behaviour (1e20 teeth became -2147483648), and TP_NO went through atoi. Now both
// are checked at their cell; empty cells keep the defaults.
TEST(ToolTable, CutAndProbeNumberMustBeWholeNumbersInRange) {
    const std::string head = "BEGIN TOOL.T MM\nT    NAME   L      TP_NO  CUT\n";
    auto table = [&](const std::string& probe, const std::string& cut) {
        return head + "1    MILL   +50    " + probe + "  " + cut + "\n[END]\n";
    };
    struct Bad {
        std::string probe, cut;
        uint32_t column;
    };
    for (const Bad& bad :
         {Bad{"1    ", "99999999999999999999", 27}, Bad{"1    ", "100", 27}, Bad{"1    ", "-4", 27},
          Bad{"1.5  ", "4", 20}, Bad{"-1   ", "4", 20}, Bad{"100000", "4", 20}}) {
        auto tools = ToolTable::parse(table(bad.probe, bad.cut), "TOOL.T");
        ASSERT_FALSE(tools.ok()) << bad.probe << " " << bad.cut;
        EXPECT_EQ(tools.error().line, 3u);
        EXPECT_EQ(tools.error().column, bad.column) << bad.probe << " " << bad.cut;
        EXPECT_NE(tools.error().message().find("needs a whole number from 0 to"), std::string::npos)
            << tools.error().message();
    }
    auto good = ToolTable::parse(table("7    ", "99"), "TOOL.T");
    ASSERT_TRUE(good.ok()) << good.error().format();
    EXPECT_EQ(good->byNumber(1)->cutterCount, 99);
    EXPECT_EQ(good->numberCell(1, "TP_NO"), 7.0);
    auto empty = ToolTable::parse(table("     ", ""), "TOOL.T");
    ASSERT_TRUE(empty.ok()) << empty.error().format();
    EXPECT_EQ(empty->byNumber(1)->cutterCount, 0);
    EXPECT_FALSE(empty->numberCell(1, "TP_NO"));
}

}  // namespace
}  // namespace kerf::tables
