#include <string>

#include <gtest/gtest.h>

#include "core/tables/datum_table.h"
#include "core/tables/point_table.h"
#include "core/tables/preset_table.h"

namespace kerf::tables {
namespace {

std::string pad(const std::string& text, size_t width) {
    return text + std::string(width - text.size(), ' ');
}

TEST(PresetTable, ReadsAxesCommentAndKeepsOtherColumns) {
    const std::string text =
        "BEGIN PRESET.PR MM\n"
        "NR   DOC          ROT      X          Y          Z          SPC      LOCKED\n"
        "0    machine      +0       +0         +0         +0         +0\n"
        "1    vice left    +1.25    +120.5     -35.125    +200       +0       L\n"
        "[END]\n";
    auto presets = PresetTable::parse(text, "PRESET.PR");
    ASSERT_TRUE(presets.ok()) << presets.error().format();
    EXPECT_EQ(presets->serialize(), text);
    ASSERT_EQ(presets->presets().size(), 2u);
    const PresetData* vice = presets->byNumber(1);
    ASSERT_NE(vice, nullptr);
    EXPECT_EQ(vice->comment, "vice left");
    EXPECT_EQ(vice->axis('X'), 120.5);
    EXPECT_EQ(vice->axis('Y'), -35.125);
    EXPECT_EQ(vice->axis('Z'), 200.0);
    EXPECT_FALSE(vice->axis('A'));  // no such column
    EXPECT_FALSE(vice->axis('Q'));  // not an axis
    const TncTable& table = presets->table();
    EXPECT_EQ(table.number(vice->row, *table.findColumn("ROT")), 1.25);
    EXPECT_EQ(table.cell(vice->row, *table.findColumn("LOCKED")), "L");
    EXPECT_EQ(presets->byNumber(2), nullptr);
}

TEST(PresetTable, DefaultTableAndEdits) {
    const std::string text = PresetTable::createDefault();
    std::string header = pad("NR", 8) + pad("DOC", 17);
    std::string zero = pad("0", 8) + pad("", 17);
    for (const char* axis : {"X", "Y", "Z", "A", "B", "C"}) {
        header += pad(axis, 14);
        zero += pad("+0", 14);
    }
    // The basic rotation column the probing cycles write (Q305 > 0).
    header += pad("SPC", 14);
    zero += pad("+0", 14);
    EXPECT_EQ(text, "BEGIN PRESET.PR MM\n" + header + "\n" + zero + "\n[END]\n");

    auto presets = PresetTable::parse(text);
    ASSERT_TRUE(presets.ok()) << presets.error().format();
    EXPECT_EQ(presets->byNumber(0)->axis('C'), 0.0);
    ASSERT_FALSE(presets->addPreset(3));
    ASSERT_FALSE(presets->setAxis(3, 'X', 125.5));
    ASSERT_FALSE(presets->setAxis(3, 'C', std::nullopt));
    EXPECT_EQ(presets->byNumber(3)->axis('X'), 125.5);
    EXPECT_FALSE(presets->byNumber(3)->axis('C'));
    std::string three = pad("3", 8) + pad("", 17) + pad("+125.5", 14);
    for (const char* value : {"+0", "+0", "+0", "+0", "", "+0"})
        three += pad(value, 14);
    EXPECT_EQ(presets->serialize(),
              "BEGIN PRESET.PR MM\n" + header + "\n" + zero + "\n" + three + "\n[END]\n");

    EXPECT_TRUE(presets->addPreset(3));
    EXPECT_TRUE(presets->setAxis(7, 'X', 1.0));
    EXPECT_TRUE(presets->setAxis(3, 'Q', 1.0));  // no axis Q
    ASSERT_FALSE(presets->removePreset(3));
    EXPECT_EQ(presets->serialize(), text);
}

TEST(PresetTable, OlderTableGetsTheColumnsItLacksWhenWritten) {
    // An older control's table: X Y Z only, no basic rotation column, CRLF, unpadded rows.
    const std::string text =
        "BEGIN PRESET.PR MM\r\n"
        "NR   DOC          X          Y          Z\r\n"
        "0                 +0         +0         -400\r\n"
        "1    vice         +120.5     -35.125    +200\r\n"
        "[END]\r\n";
    auto presets = PresetTable::parse(text, "PRESET.PR");
    ASSERT_TRUE(presets.ok()) << presets.error().format();
    EXPECT_FALSE(presets->basicRotationColumn());
    EXPECT_EQ(presets->basicRotationDeg(1), 0.0);
    ASSERT_FALSE(presets->setBasicRotation(1, 0.7));
    ASSERT_FALSE(presets->setAxis(0, 'C', 12.5));
    // Z's widest cell ends at byte 44: SPC starts one space later, C 14 bytes after SPC.
    EXPECT_EQ(presets->serialize(),
              "BEGIN PRESET.PR MM\r\n" + pad("NR   DOC          X          Y          Z", 45) +
                  pad("SPC", 14) + "C\r\n" +
                  pad("0                 +0         +0         -400", 59) + "+12.5\r\n" +
                  pad("1    vice         +120.5     -35.125    +200", 45) + "+0.7\r\n" +
                  "[END]\r\n");
    EXPECT_EQ(presets->basicRotationDeg(1), 0.7);
    EXPECT_EQ(presets->byNumber(1)->axis('Y'), -35.125);
    EXPECT_EQ(presets->byNumber(0)->axis('C'), 12.5);
    // Emptying an axis the table lacks adds nothing; a column no preset table has is refused.
    ASSERT_FALSE(presets->setAxis(0, 'W', std::nullopt));
    EXPECT_FALSE(presets->table().findColumn("W"));
}

TEST(PresetTable, BasicRotationGoesToRotInATableWithoutSpc) {
    // iTNC 530 tables keep the basic rotation in ROT.
    const std::string text =
        "BEGIN PRESET.PR MM\n"
        "NR   DOC   ROT      X        Y        Z\n"
        "0          +1.5     +0       +0       +0\n"
        "[END]\n";
    auto presets = PresetTable::parse(text, "PRESET.PR");
    ASSERT_TRUE(presets.ok()) << presets.error().format();
    EXPECT_EQ(presets->basicRotationDeg(0), 1.5);
    ASSERT_FALSE(presets->setBasicRotation(0, -0.25));
    EXPECT_EQ(presets->basicRotationDeg(0), -0.25);
    EXPECT_FALSE(presets->table().findColumn("SPC"));
}

TEST(DatumTable, EmptyCellMeansNoShift) {
    const std::string text =
        "BEGIN NULLTAB.D MM\n"
        "D      X           Y           Z           DOC\n"
        "0      +117.524    +50.002     +0          fixture left\n"
        "1      +200.524    +50.007                 no Z shift\n"
        "[END]\n";
    auto datums = DatumTable::parse(text);
    ASSERT_TRUE(datums.ok()) << datums.error().format();
    EXPECT_EQ(datums->serialize(), text);
    const DatumData* one = datums->byNumber(1);
    ASSERT_NE(one, nullptr);
    EXPECT_EQ(one->axis('X'), 200.524);
    EXPECT_EQ(one->axis('Y'), 50.007);
    EXPECT_FALSE(one->axis('Z'));
    EXPECT_EQ(one->comment, "no Z shift");
    EXPECT_EQ(datums->byNumber(0)->axis('Z'), 0.0);

    ASSERT_FALSE(datums->setAxis(1, 'Z', -12.0));
    EXPECT_EQ(datums->serialize(),
              "BEGIN NULLTAB.D MM\n"
              "D      X           Y           Z           DOC\n"
              "0      +117.524    +50.002     +0          fixture left\n"
              "1      +200.524    +50.007     -12         no Z shift\n"
              "[END]\n");
}

TEST(DatumTable, AcceptsAnNrKeyColumnAndUnsignedNumbers) {
    auto datums = DatumTable::parse(
        "BEGIN D2.D MM\nNR  X        Y       Z\n0   117.524  50.002  0\n4   0.0      0.0     0.0\n"
        "[END]\n");
    ASSERT_TRUE(datums.ok()) << datums.error().format();
    EXPECT_EQ(datums->byNumber(4)->axis('Y'), 0.0);
    ASSERT_FALSE(datums->setAxis(0, 'X', 1.5));
    EXPECT_EQ(datums->table().cell(0, 1), "1.500");
    ASSERT_FALSE(datums->addDatum(2));
    EXPECT_EQ(datums->byNumber(2)->row, 1u);
    EXPECT_EQ(datums->table().cell(1, 0), "2");
}

TEST(DatumTable, DefaultTable) {
    const std::string text = DatumTable::createDefault("FIXTURES", TableUnit::Inch);
    EXPECT_EQ(text.substr(0, text.find('\n')), "BEGIN FIXTURES.D INCH");
    auto datums = DatumTable::parse(text);
    ASSERT_TRUE(datums.ok()) << datums.error().format();
    EXPECT_EQ(datums->table().columns().front().name, "D");
    EXPECT_EQ(datums->table().columns().back().name, "DOC");
    EXPECT_EQ(datums->byNumber(0)->axis('B'), 0.0);
}

const std::string kPoints =
    "BEGIN TAB1.PNT MM\n"
    "NR  X    Y    Z    FADE CLEAR\n"
    "0   +10  +10  +0\n"
    "1   +40  +30  +0   Y\n"
    "2   +90  +10  +0        Y\n"
    "[END]\n";

TEST(PointTable, ReadsPositionsAndFlags) {
    auto points = PointTable::parse(kPoints);
    ASSERT_TRUE(points.ok()) << points.error().format();
    ASSERT_EQ(points->points().size(), 3u);
    const PointData& one = points->points()[1];
    EXPECT_EQ(one.number, 1);
    EXPECT_EQ(one.axis('X'), 40.0);
    EXPECT_EQ(one.axis('Y'), 30.0);
    EXPECT_TRUE(one.fade);
    EXPECT_FALSE(one.clear);
    EXPECT_FALSE(points->byNumber(0)->fade);
    EXPECT_TRUE(points->byNumber(2)->clear);
    EXPECT_FALSE(points->byNumber(2)->fade);
}

TEST(PointTable, EditsFlagsAndPositions) {
    auto points = PointTable::parse(kPoints);
    ASSERT_TRUE(points.ok());
    ASSERT_FALSE(points->setFade(0, true));
    ASSERT_FALSE(points->setFade(1, false));
    ASSERT_FALSE(points->setAxis(2, 'Y', 12.0));
    EXPECT_EQ(points->serialize(),
              "BEGIN TAB1.PNT MM\n"
              "NR  X    Y    Z    FADE CLEAR\n"
              "0   +10  +10  +0   Y\n"
              "1   +40  +30  +0   \n"
              "2   +90  +12  +0        Y\n"
              "[END]\n");
    EXPECT_TRUE(points->byNumber(0)->fade);
    // "+12.5" would leave no space before Z; rounding it would move the point.
    auto tooWide = points->setAxis(2, 'Y', 12.5);
    ASSERT_TRUE(tooWide);
    EXPECT_EQ(tooWide->line, 5u);
    EXPECT_EQ(tooWide->column, 10u);
    EXPECT_TRUE(points->setFade(9, true));
}

TEST(PointTable, DefaultTableHasNoPoints) {
    const std::string text = PointTable::createDefault("HOLES");
    EXPECT_EQ(text, "BEGIN HOLES.PNT MM\n" + pad("NR", 8) + pad("X", 14) + pad("Y", 14) +
                        pad("Z", 14) + pad("FADE", 5) + pad("CLEAR", 6) + "\n[END]\n");
    auto points = PointTable::parse(text);
    ASSERT_TRUE(points.ok()) << points.error().format();
    EXPECT_TRUE(points->points().empty());
    ASSERT_FALSE(points->addPoint(0));
    ASSERT_FALSE(points->setAxis(0, 'X', 10.0));
    EXPECT_EQ(points->serialize(), "BEGIN HOLES.PNT MM\n" + pad("NR", 8) + pad("X", 14) +
                                       pad("Y", 14) + pad("Z", 14) + pad("FADE", 5) +
                                       pad("CLEAR", 6) + "\n" + pad("0", 8) + pad("+10", 14) +
                                       pad("+0", 14) + pad("+0", 14) + pad("", 11) + "\n[END]\n");
}

}  // namespace
}  // namespace kerf::tables
