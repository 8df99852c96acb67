#include <cmath>

#include <gtest/gtest.h>

#include "core/interp/fagor/tables/table_text.h"
#include "core/interp/fagor/tables/tool_offset_table.h"
#include "core/interp/fagor/tables/tool_table.h"
#include "core/interp/fagor/tables/tool_touch_off.h"
#include "core/interp/fagor/tables/zero_offset_table.h"

namespace kerf::fagor {
namespace {

TEST(FagorToolTouchOff, TheLengthPutsTheTipAtTheKnownPosition) {
    auto table = ToolOffsetTable::parse("D1 X10 Z-30 I0.2 K-0.1 F3\n", "t.tab");
    ASSERT_TRUE(table.ok());
    // D1 active (X 10 + I 0.2) shows the tip at r24 on a part turned to D50 (r25): the holder
    // stands at 24 - 10.2 = 13.8, so X = 25 - 13.8 - 0.2 = 11, one more than before.
    ASSERT_TRUE(touchOff(*table, {1, Axis::X, 24.0, 25.0, 10.2}));
    EXPECT_DOUBLE_EQ(table->get(1).x, 11.0);
    EXPECT_DOUBLE_EQ(table->get(1).wearX, 0.2);
    // D2 calibrated on the face Z0 while no offset is active (D0): the tip shows Z-42.5, the
    // holder stands there, so Z = 0 - (-42.5) - 0 = 42.5; X of D2 stays 0.
    ASSERT_TRUE(touchOff(*table, {2, Axis::Z, -42.5, 0.0, 0.0}));
    EXPECT_DOUBLE_EQ(table->get(2).z, 42.5);
    EXPECT_DOUBLE_EQ(table->get(2).x, 0.0);
    EXPECT_EQ(table->serialize(), "D1 X11 Z-30 I0.2 K-0.1 F3\nD2 Z42.5\n");
    EXPECT_FALSE(touchOff(*table, {0, Axis::X, 1.0, 2.0, 0.0}));
    EXPECT_FALSE(touchOff(*table, {256, Axis::X, 1.0, 2.0, 0.0}));
    EXPECT_FALSE(touchOff(*table, {1, Axis::Y, 1.0, 2.0, 0.0}));
    EXPECT_FALSE(touchOff(*table, {1, Axis::X, 1.0, std::nan(""), 0.0}));
    EXPECT_DOUBLE_EQ(table->get(1).x, 11.0);
}

TEST(FagorTableText, UnmodifiedTableGivesBackTheSameBytes) {
    const std::string bytes =
        "%TOOL OFFSETS,MX,\r\n; comment line\r\n\r\nD1 X+12.5 Z-30   F3 R0.8 ; note\r\nD2 X0";
    auto table = TableText::parse(bytes, "t.tab");
    ASSERT_TRUE(table.ok());
    EXPECT_EQ(table->serialize(), bytes);
    ASSERT_EQ(table->rows().size(), 2u);
    EXPECT_EQ(table->rows()[0].key, "D1");
    ASSERT_NE(table->rows()[0].field("Z"), nullptr);
    EXPECT_DOUBLE_EQ(table->rows()[0].field("Z")->value, -30.0);
    EXPECT_EQ(table->rows()[0].field("I"), nullptr);
}

TEST(FagorTableText, EditRewritesOnlyTheField) {
    auto table = TableText::parse("D1 X+12.5 Z-30 F3\nD2 X0\n", "t.tab");
    ASSERT_TRUE(table.ok());
    table->set("D1", "X", 7.25);     // keeps the explicit '+'
    table->set("D1", "R", 0.4);      // appended after the last field
    table->set("D3", "Z", -1.5);     // a new row
    table->set("D2", "X", 1.0 / 3);  // four decimals
    EXPECT_EQ(table->serialize(), "D1 X+7.25 Z-30 F3 R0.4\nD2 X0.3333\nD3 Z-1.5\n");
}

TEST(FagorTableText, RemovedRowTakesItsLineAndLaterRowsStayEditable) {
    auto table = TableText::parse("%TOOL OFFSETS,MX,\nD1 X1 ; first\nD2 X2\nD3 X3\n", "t.tab");
    ASSERT_TRUE(table.ok());
    EXPECT_TRUE(table->removeRow("D1"));
    EXPECT_FALSE(table->removeRow("D7"));
    table->set("D3", "Z", 4.0);
    EXPECT_EQ(table->serialize(), "%TOOL OFFSETS,MX,\nD2 X2\nD3 X3 Z4\n");
    ASSERT_EQ(table->rows().size(), 2u);
    EXPECT_EQ(table->rows()[0].line, 1u);
}

TEST(FagorTableText, ErrorsNameLineAndColumn) {
    auto bad = TableText::parse("D1 X1\nD2 X1 Zabc\n", "t.tab");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().line, 2u);
    EXPECT_EQ(bad.error().column, 7u);
    auto twice = TableText::parse("D1 X1\nD1 X2\n", "t.tab");
    ASSERT_FALSE(twice.ok());
    EXPECT_EQ(twice.error().line, 2u);
}

TEST(FagorTableText, NumbersAsWritten) {
    EXPECT_EQ(formatTableNumber(10.0), "10");
    EXPECT_EQ(formatTableNumber(-0.25), "-0.25");
    EXPECT_EQ(formatTableNumber(-0.00001), "0");
    EXPECT_EQ(formatTableNumber(3.14159265, 4), "3.1416");
}

TEST(FagorToolOffsetTable, ReadsFieldsAndChecksLocationCodes) {
    auto table = ToolOffsetTable::parse("D1 X12.5 Z-30 F3 R0.8 I0.1 K-0.2\n", "o.tab");
    ASSERT_TRUE(table.ok());
    const ToolOffset d1 = table->get(1);
    EXPECT_DOUBLE_EQ(d1.x, 12.5);
    EXPECT_DOUBLE_EQ(d1.z, -30.0);
    EXPECT_EQ(d1.location, 3);
    EXPECT_DOUBLE_EQ(d1.radius, 0.8);
    EXPECT_DOUBLE_EQ(d1.wearX, 0.1);
    EXPECT_DOUBLE_EQ(d1.wearZ, -0.2);
    EXPECT_DOUBLE_EQ(table->get(7).x, 0.0);  // offsets without a row are zero
    EXPECT_FALSE(ToolOffsetTable::parse("D1 F10\n").ok());
    EXPECT_FALSE(ToolOffsetTable::parse("D256 X1\n").ok());
    EXPECT_FALSE(ToolOffsetTable::parse("D1 Q1\n").ok());
    EXPECT_FALSE(table->set(1, 'F', 2.5));
    EXPECT_TRUE(table->set(2, 'R', 1.2));
    EXPECT_TRUE(table->modified());
    EXPECT_DOUBLE_EQ(table->get(2).radius, 1.2);
}

TEST(FagorZeroOffsetTable, SelectionAndAdditiveOffsets) {
    // The manual's table (E10, with the G58 value read as -90).
    auto table = ZeroOffsetTable::parse(
        "G54 X0 Z330\nG55 X0 Z240\nG56 X0 Z150\nG58 X0 Z-90\nG59 X0 Z-180\nG159N20 X5\n"
        "PLC Z0.5\nACTIVE G54 G58\n",
        "z.tab");
    ASSERT_TRUE(table.ok()) << table.error().message();
    EXPECT_EQ(table->selection().absolute, 1);
    EXPECT_EQ(table->selection().additive, 5);
    EXPECT_DOUBLE_EQ(table->selectedOffset()[Axis::Z], 240.0);  // 330 - 90
    EXPECT_DOUBLE_EQ(table->offset(20)[Axis::X], 5.0);
    EXPECT_DOUBLE_EQ(table->plcOffset()[Axis::Z], 0.5);
    ZeroOffsetSelection g159;
    g159.absolute = 6;
    g159.byG159 = true;
    table->setSelection(g159);
    EXPECT_DOUBLE_EQ(table->selectedOffset()[Axis::Z], -180.0);  // G59's values, absolute
    EXPECT_NE(table->serialize().find("ACTIVE G159 N6"), std::string::npos);
    auto again = ZeroOffsetTable::parse(table->serialize());
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->selection(), g159);
}

TEST(FagorZeroOffsetTable, PresetSelectionRoundTrips) {
    ZeroOffsetTable table = ZeroOffsetTable::createDefault();
    ZeroOffsetSelection preset;
    preset.preset = true;
    preset.presetOffset[Axis::Z] = 112.5;
    table.setSelection(preset);
    auto again = ZeroOffsetTable::parse(table.serialize());
    ASSERT_TRUE(again.ok());
    EXPECT_TRUE(again->selection().preset);
    EXPECT_DOUBLE_EQ(again->selectedOffset()[Axis::Z], 112.5);
    EXPECT_FALSE(ZeroOffsetTable::parse("G60 X1\n").ok());
    EXPECT_FALSE(ZeroOffsetTable::parse("G54 Q1\n").ok());
}

// Adversarial pass 2026-11-28: the ACTIVE row's G and N values were converted to int unchecked
// (G99999999999 is undefined behaviour; G54.5 was read as G54). Each is an error at its field.
TEST(FagorZeroOffsetTable, ActiveNumbersBeyondIntOrWithDecimalsAreErrors) {
    struct Bad {
        const char* text;
        uint32_t column;
    };
    for (const Bad& bad : {Bad{"ACTIVE G99999999999\n", 8}, Bad{"ACTIVE G54.5\n", 8},
                           Bad{"ACTIVE G159 N99999999999\n", 13}, Bad{"ACTIVE G159 N7.5\n", 13}}) {
        auto table = ZeroOffsetTable::parse(bad.text, "z.tab");
        ASSERT_FALSE(table.ok()) << bad.text;
        EXPECT_EQ(table.error().line, 1u) << bad.text;
        EXPECT_EQ(table.error().column, bad.column) << bad.text;
    }
    auto good = ZeroOffsetTable::parse("G159N7 X5\nACTIVE G159 N7\n", "z.tab");
    ASSERT_TRUE(good.ok()) << good.error().message();
    EXPECT_EQ(good->selection().absolute, 7);
}

TEST(FagorToolTable, OffsetOfAToolDefaultsToItsNumber) {
    auto table = ToolTable::parse("T3 D17 FAM201 NOSEA35 NOSEW3 CUTA60\n");
    ASSERT_TRUE(table.ok());
    EXPECT_EQ(table->get(3).offset, 17);
    EXPECT_EQ(table->get(3).family, 201);
    EXPECT_DOUBLE_EQ(table->get(3).noseWidth, 3.0);
    EXPECT_EQ(table->get(5).offset, 5);
    EXPECT_FALSE(ToolTable::parse("T1 D300\n").ok());
    EXPECT_FALSE(ToolTable::parse("X1 D3\n").ok());
}

}  // namespace
}  // namespace kerf::fagor
