// Canned cycle blocks G66-G89 (spec part 2 §2): after the cycle's G the letters are its
// parameters, with the formats, ranges and required/optional rules of each cycle.
#include <gtest/gtest.h>

#include "core/interp/fagor/block_parser.h"

namespace kerf::fagor {
namespace {

ParsedBlock parse(std::string_view text, ParameterSource* source = nullptr) {
    BlockParser parser(source);
    ParsedBlock block;
    EXPECT_TRUE(parser.parse(text, false, block))
        << text << ": " << parser.problem().messageTemplate;
    return block;
}

Problem problem(std::string_view text, ParameterSource* source = nullptr) {
    BlockParser parser(source);
    ParsedBlock block;
    EXPECT_FALSE(parser.parse(text, false, block)) << text;
    return parser.problem();
}

class Values final : public ParameterSource {
public:
    bool parameter(int number, double& out, Problem&) override {
        out = number == 1 ? -2.0 : number == 2 ? 0.0 : 3.0;
        return true;
    }
};

TEST(FagorCycleBlock, EveryCycleTakesItsOwnLetters) {
    // The words the old parser refused: E ("belongs to G51"), M ("format 4.0"), H (unknown).
    const ParsedBlock g81 = parse("G81 X80 Z2 Q60 R-50 C2 D1 L0.5 M0.2 F0.3 H0.1");
    ASSERT_EQ(g81.iso.cycle.g, 81);
    EXPECT_DOUBLE_EQ(g81.iso.cycle['M'].value, 0.2);
    EXPECT_DOUBLE_EQ(g81.iso.cycle['H'].value, 0.1);
    EXPECT_DOUBLE_EQ(g81.iso.cycle['R'].value, -50.0);
    EXPECT_FALSE(g81.iso.has(Axis::X));  // cycle parameters are not axis words
    EXPECT_FALSE(g81.iso.f.present);
    EXPECT_EQ(g81.outOfOrder, 0);  // F before M is the cycle's own order
    const ParsedBlock g66 = parse("G66 X20 Z100 I8 C2 A0 L-0.5 M0.3 H0.1 S100 E200 Q12");
    EXPECT_EQ(g66.iso.cycle.g, 66);
    EXPECT_DOUBLE_EQ(g66.iso.cycle['E'].value, 200.0);
    EXPECT_DOUBLE_EQ(g66.iso.cycle['L'].value, -0.5);
    EXPECT_EQ(parse("G68 X0 Z100 C2 D1 L0.4 M0.2 K0.1 F0.25 H0.12 S10 E20").iso.cycle.g, 68);
    EXPECT_EQ(parse("G69 X0 Z100 C2 S10 E20").iso.cycle.g, 69);
    EXPECT_EQ(parse("G82 X80 Z0 Q40 R-5 C1").iso.cycle.g, 82);
    EXPECT_EQ(parse("G83 X0 Z0 I20 B5 D2 K150 H1 C1 L1 R0.8").iso.cycle['K'].value, 150.0);
    EXPECT_EQ(parse("G84 X40 Z0 Q60 R-10 C2 I20 K-10").iso.cycle['I'].value, 20.0);
    EXPECT_EQ(parse("G85 X40 Z0 Q60 R-10 C2 D0 I20 K-10").iso.cycle['D'].value, 0.0);
    const ParsedBlock g86 =
        parse("G86 X60 Z10 Q60 R-40 I2 B0.5 E0.1 D1 L0.1 C2 J3 A30 W120 V2 M0.1");
    EXPECT_DOUBLE_EQ(g86.iso.cycle['W'].value, 120.0);
    EXPECT_DOUBLE_EQ(g86.iso.cycle['V'].value, 2.0);
    EXPECT_EQ(parse("G87 X60 Z0 Q20 R0 K40 I-1 B-0.2 C1.5 W0").iso.cycle.g, 87);
    EXPECT_EQ(parse("G88 X60 Z-10 Q50 R-20 C2 D1 K50").iso.cycle.g, 88);
    const ParsedBlock g89 = parse("G90 G89 X30 Z0 Q40 R-5 N3");
    EXPECT_EQ(g89.iso.cycle.g, 89);
    EXPECT_EQ(g89.iso.gCount, 2);
    EXPECT_EQ(g89.repetition, 3);
    EXPECT_EQ(parse("G01 X10 Z5").iso.cycle.g, -1);
}

TEST(FagorCycleBlock, MissingRequiredParameterIsReportedAtTheCycle) {
    Problem p = problem("N5 G81 X80 Z2 Q60 R-50");
    EXPECT_EQ(p.offset, 3u);
    EXPECT_EQ(p.messageTemplate, "{1} needs its parameter {2}");
    EXPECT_EQ(p.args, (std::vector<std::string>{"G81", "C"}));
    EXPECT_EQ(problem("G66 X20 Z100 I8 C2 S100").args[1], "E");
    EXPECT_EQ(problem("G83 X0 Z0 I20").args[1], "B");
    EXPECT_EQ(problem("G86 X60 Z10 Q60 R-40 I2 B0.5").args[1], "C");
    EXPECT_EQ(problem("G84 X40 Z0 Q60 R-10 C2 I20").args[1], "K");
}

TEST(FagorCycleBlock, OutOfRangeValuesAreReportedAtTheirParameter) {
    //                 0         1         2
    //                 0123456789012345678901234
    Problem p = problem("G81 X80 Z2 Q60 R-50 C0");
    EXPECT_EQ(p.offset, 20u);
    EXPECT_EQ(p.messageTemplate, "{1} of {2} cannot be 0");
    EXPECT_EQ(problem("G81 X80 Z2 Q60 R-50 C-2").offset, 20u);  // unsigned format
    EXPECT_EQ(problem("G81 X80 Z2 Q60 R-50 C-2").messageTemplate, "{1} cannot be negative");
    EXPECT_EQ(problem("G83 X0 Z0 I0 B5").offset, 10u);
    EXPECT_EQ(problem("G86 X60 Z10 Q60 R-40 I2 B0 C2").offset, 24u);
    EXPECT_EQ(problem("G86 X60 Z10 Q60 R-40 I2 B1 C0").offset, 27u);
    EXPECT_EQ(problem("G88 X60 Z-10 Q50 R-20 C0").offset, 22u);
    // Whole numbers: A is 0 or 1, labels 4 digits, the dwell K 5 digits.
    EXPECT_EQ(problem("G66 X20 Z100 I8 C2 A2 S1 E2").offset, 19u);
    EXPECT_EQ(problem("G66 X20 Z100 I8 C2 S12345 E2").offset, 19u);
    EXPECT_EQ(problem("G66 X20 Z100 I8 C2 S1 E2.5").offset, 22u);
    EXPECT_EQ(problem("G83 X0 Z0 I20 B5 K1.5").offset, 17u);
    EXPECT_EQ(problem("G81 X123456 Z2 Q60 R-50 C1").offset, 4u);
    // Letters that are not the cycle's.
    p = problem("G88 X60 Z-10 Q50 R-20 F1");
    EXPECT_EQ(p.offset, 22u);
    EXPECT_EQ(p.args, (std::vector<std::string>{"F", "G88"}));
    EXPECT_EQ(problem("G81 X80 Z2 Q60 R-50 C1 C2").offset, 23u);
    EXPECT_EQ(problem("G81 G88 X1").offset, 4u);
    // G86: K (repass) and M (variable pitch) together.
    EXPECT_EQ(problem("G86 X60 Z10 Q60 R-40 K0 I2 B1 C2 M0.1").offset, 33u);
}

TEST(FagorCycleBlock, ParameterValuesAreCheckedWhenKnown) {
    // Without a parameter source (program check) P values are unknown; at execution they count.
    parse("G81 X80 Z2 Q60 R-50 CP1");
    parse("G81 X80 Z2 Q60 R-50 CP2");
    Values values;
    EXPECT_EQ(problem("G81 X80 Z2 Q60 R-50 CP1", &values).offset, 20u);
    EXPECT_EQ(problem("G81 X80 Z2 Q60 R-50 CP2", &values).messageTemplate,
              "{1} of {2} cannot be 0");
    EXPECT_DOUBLE_EQ(parse("G81 XP3 Z2 Q60 R-50 CP3", &values).iso.cycle['X'].value, 3.0);
}

}  // namespace
}  // namespace kerf::fagor
