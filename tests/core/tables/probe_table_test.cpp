#include "core/tables/probe_table.h"

#include <string>

#include <gtest/gtest.h>

namespace kerf::tables {
namespace {

TEST(ProbeTable, DefaultTableHasEveryColumnOfTheSpecAndProbeOne) {
    // Widths: NO 5, TYPE 11, CAL_OF1 11, CAL_OF2 11, CAL_ANG 9, F 9, FMAX 9, DIST 8, SET_UP 8,
    // F_PREPOS 14, TRACK 7, SERIAL 12.
    const std::string expected =
        "BEGIN TCHPROBE.TP MM\n"
        "NO   TYPE       CAL_OF1    CAL_OF2    CAL_ANG  F        FMAX     DIST    SET_UP  "
        "F_PREPOS      TRACK  SERIAL      \n"
        "1    TS460      +0         +0         +0       1000     3000     20      2       "
        "FMAX_PROBE    OFF                \n"
        "[END]\n";
    EXPECT_EQ(ProbeTable::createDefault(), expected);
    auto probes = ProbeTable::parse(expected, "tchprobe.tp");
    ASSERT_TRUE(probes.ok()) << probes.error().format();
    ASSERT_EQ(probes->probes().size(), 1u);
    const ProbeData* probe = probes->byNumber(1);
    ASSERT_NE(probe, nullptr);
    EXPECT_EQ(probe->type, "TS460");
    EXPECT_EQ(probe->probingFeed, 1000.0);
    EXPECT_EQ(probe->rapidFeed, 3000.0);
    EXPECT_EQ(probe->maxProbingPath, 20.0);
    EXPECT_EQ(probe->setUpClearance, 2.0);
    EXPECT_FALSE(probe->prepositionAtMachineRapid);
    EXPECT_FALSE(probe->track);
}

TEST(ProbeTable, ReadsCalibrationAndChoices) {
    const std::string text =
        "BEGIN TCHPROBE.TP MM\n"
        "NO TYPE   CAL_OF1 CAL_OF2 CAL_ANG F    FMAX DIST SET_UP F_PREPOS     TRACK SERIAL\n"
        "1  TS460  +0.012  -0.008  +90     500  2000 15   1.5    FMAX_MACHINE ON    12345\n"
        "3  TS260  +0      +0      +0      300  1000 10   2      FMAX_PROBE   OFF\n"
        "[END]\n";
    auto probes = ProbeTable::parse(text, "tchprobe.tp");
    ASSERT_TRUE(probes.ok()) << probes.error().format();
    EXPECT_EQ(probes->serialize(), text);
    const ProbeData* first = probes->byNumber(1);
    ASSERT_NE(first, nullptr);
    EXPECT_DOUBLE_EQ(first->centreOffsetMain, 0.012);
    EXPECT_DOUBLE_EQ(first->centreOffsetSecondary, -0.008);
    EXPECT_EQ(first->calibrationAngle, 90.0);
    EXPECT_EQ(first->setUpClearance, 1.5);
    EXPECT_TRUE(first->prepositionAtMachineRapid);
    EXPECT_TRUE(first->track);
    EXPECT_EQ(first->serial, "12345");
    ASSERT_NE(probes->byNumber(3), nullptr);
    EXPECT_FALSE(probes->byNumber(3)->track);
    EXPECT_EQ(probes->byNumber(2), nullptr);
}

TEST(ProbeTable, RefusesBadValuesAtTheirCell) {
    const std::string header =
        "BEGIN TCHPROBE.TP MM\n"
        "NO TYPE   F    DIST TRACK\n";
    auto track = ProbeTable::parse(header + "1  TS460  500  15   YES\n[END]\n", "tchprobe.tp");
    ASSERT_FALSE(track.ok());
    EXPECT_EQ(track.error().line, 3u);
    EXPECT_EQ(track.error().column, 21u);
    EXPECT_NE(track.error().format().find("column TRACK needs OFF or ON, not \"YES\""),
              std::string::npos)
        << track.error().format();
    auto feed = ProbeTable::parse(header + "1  TS460  0    15   ON\n[END]\n", "tchprobe.tp");
    ASSERT_FALSE(feed.ok());
    EXPECT_EQ(feed.error().column, 11u);
    EXPECT_NE(feed.error().format().find("column F must be greater than 0"), std::string::npos);
    auto duplicate = ProbeTable::parse(
        header + "1  TS460  500  15   ON\n1  TS460  500  15   ON\n[END]\n", "tchprobe.tp");
    EXPECT_FALSE(duplicate.ok());
}

TEST(ProbeTable, TypeNamesAModelThatDecidesOrientation) {
    // Spec 1.3: TYPE says how the probe can be oriented. HEIDENHAIN's cable probes turn to two
    // directions (a reversal is possible, tracking is not), the infrared ones to any.
    auto probes = ProbeTable::parse(
        "BEGIN TCHPROBE.TP MM\nNO TYPE     F    TRACK\n1  TS 260   500  OFF\n"
        "2  ts642    500  ON\n3           500  OFF\n4  FIXED    500  OFF\n[END]\n",
        "tchprobe.tp");
    ASSERT_TRUE(probes.ok()) << probes.error().format();
    const ProbeType& cable = *probes->byNumber(1)->model;
    EXPECT_EQ(cable.name, "TS260");
    EXPECT_EQ(cable.orientation, ProbeOrientation::TwoDirections);
    EXPECT_EQ(cable.signal, SignalTransmission::Cable);
    EXPECT_TRUE(canReverse(cable));
    EXPECT_EQ(probes->byNumber(2)->model->orientation, ProbeOrientation::Any);
    EXPECT_EQ(probes->byNumber(2)->model->signal, SignalTransmission::Infrared);
    EXPECT_EQ(probes->byNumber(3)->model->name, "TS460");  // empty: the new row's default
    EXPECT_FALSE(canReverse(*probes->byNumber(4)->model));
    // An unknown model and tracking with a probe that cannot follow are errors at their cell.
    auto unknown = ProbeTable::parse(
        "BEGIN TCHPROBE.TP MM\nNO TYPE     F\n1  OMP40    500\n[END]\n", "tchprobe.tp");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().line, 3u);
    EXPECT_EQ(unknown.error().column, 4u);
    EXPECT_NE(unknown.error().format().find("unknown probe \"OMP40\""), std::string::npos)
        << unknown.error().format();
    auto track = ProbeTable::parse(
        "BEGIN TCHPROBE.TP MM\nNO TYPE     F    TRACK\n1  TS260    500  ON\n[END]\n",
        "tchprobe.tp");
    ASSERT_FALSE(track.ok());
    EXPECT_EQ(track.error().column, 18u);
    EXPECT_NE(track.error().format().find("TS260 cannot be"), std::string::npos)
        << track.error().format();
}

TEST(ProbeTable, CalibrationWritesTheCentreOffsetAddingMissingColumns) {
    // A table without CAL_OF1/CAL_OF2 (an older control's): calibration adds them at the end,
    // CAL_OF1 one space after DIST's widest cell, CAL_OF2 11 bytes later.
    auto probes = ProbeTable::parse(
        "BEGIN TCHPROBE.TP MM\nNO   TYPE   F     DIST\n1    TS460  1000  20\n"
        "2    TS260  500   10\n[END]\n");
    ASSERT_TRUE(probes.ok()) << probes.error().format();
    ASSERT_FALSE(probes->setCentreOffset(2, 0.03, -0.0215));
    EXPECT_EQ(probes->serialize(),
              "BEGIN TCHPROBE.TP MM\nNO   TYPE   F     DIST CAL_OF1    CAL_OF2\n"
              "1    TS460  1000  20\n2    TS260  500   10   +0.03      -0.0215\n[END]\n");
    EXPECT_EQ(probes->byNumber(2)->centreOffsetMain, 0.03);
    EXPECT_EQ(probes->byNumber(2)->centreOffsetSecondary, -0.0215);
    EXPECT_EQ(probes->byNumber(1)->centreOffsetMain, 0.0);
    EXPECT_TRUE(probes->setCentreOffset(3, 0.0, 0.0));  // no probe 3
}

}  // namespace
}  // namespace kerf::tables
