#include "ui/testrun/machine_follower.h"

#include <variant>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "test_paths.h"

namespace kerf::ui {
namespace {

// Cycle 200 at X10 Y10, one plunge: rapid to the set-up clearance Z+2, feed to Z-6, rapid back
// over the same line to the 2nd set-up clearance Z+5. Then two ordinary blocks.
// Line 12 is the CYCL CALL, 13 and 14 the moves after it.
const char* kDrill =
    "0 BEGIN PGM DRILL MM\n"
    "1 L X+10 Y+10 Z+5 R0 FMAX\n"
    "2 CYCL DEF 200 DRILLING ~\n"
    "  Q200=2 ;SET-UP CLEARANCE ~\n"
    "  Q201=-6 ;DEPTH ~\n"
    "  Q206=150 ;FEED RATE FOR PLNGNG ~\n"
    "  Q202=6 ;PLUNGING DEPTH ~\n"
    "  Q210=0 ;DWELL TIME AT TOP ~\n"
    "  Q203=+0 ;SURFACE COORDINATE ~\n"
    "  Q204=5 ;2ND SET-UP CLEARANCE ~\n"
    "  Q211=0 ;DWELL TIME AT DEPTH\n"
    "3 CYCL CALL\n"
    "4 L X+30 R0 F500\n"
    "5 L X+10 R0 F500\n"
    "6 END PGM DRILL MM\n";

class Follower : public testing::Test {
protected:
    Follower() {
        TestRunInput input;
        input.text = kDrill;
        input.path = kerf::test::uniqueTempDir("follower") / "DRILL.H";
        input.machine = *machine::loadMachine("mill");
        program = interpretForTestRun(input);
    }
    // The location of the program's commands on a line (the block the machine reports).
    SourceLocation blockOnLine(uint32_t line) const {
        for (const canon::Command& c : program.commands)
            if (c.location.line == line) return c.location;
        ADD_FAILURE() << "no command on line " << line;
        return {};
    }
    const canon::Command& at(const MachineFollower& follower) const {
        return program.commands[follower.point().command];
    }
    TestRunProgram program;
};

TEST_F(Follower, TakesTheRetractOverThePlungeWhenTheToolGoesUp) {
    ASSERT_TRUE(program.ran);
    MachineFollower follower(program);
    const SourceLocation cycle = blockOnLine(12);
    follower.observe(cycle, {10.0, 10.0, 2.0});
    follower.observe(cycle, {10.0, 10.0, -2.0});
    // Going down: the plunge at Q206, halfway from Z+2 to Z-6.
    ASSERT_TRUE(std::holds_alternative<canon::LinearMove>(at(follower).body));
    EXPECT_NEAR(follower.point().fraction, 0.5, 1e-9);
    EXPECT_DOUBLE_EQ(std::get<canon::LinearMove>(at(follower).body).feed, 150.0);
    follower.observe(cycle, {10.0, 10.0, -6.0});
    follower.observe(cycle, {10.0, 10.0, -4.0});
    // Going up along the same line: the rapid retract, 2 of its 11 mm from Z-6 to Z+5.
    ASSERT_TRUE(std::holds_alternative<canon::RapidMove>(at(follower).body));
    EXPECT_NEAR(std::get<canon::RapidMove>(at(follower).body).target[Axis::Z], 5.0, 1e-9);
    EXPECT_NEAR(follower.point().fraction, 2.0 / 11.0, 1e-9);
    // Standing still there it stays; it never goes back to the plunge.
    const RunPoint retract = follower.point();
    follower.observe(cycle, {10.0, 10.0, -4.0});
    follower.observe(cycle, {10.0, 10.0, -5.0});
    EXPECT_EQ(follower.point().command, retract.command);
    EXPECT_GE(follower.point().fraction, retract.fraction);
}

TEST_F(Follower, FindsTheNextBlockAheadAndIgnoresOnesItDoesNotKnow) {
    MachineFollower follower(program);
    EXPECT_FALSE(follower.startPoint());
    // The machine started at block 4 (Start at block): the run begins there.
    follower.observe(blockOnLine(13), {20.0, 10.0, 5.0});
    ASSERT_TRUE(follower.startPoint());
    EXPECT_EQ(program.commands[follower.startPoint()->command].location.line, 13u);
    EXPECT_NEAR(follower.point().fraction, 0.5, 1e-9);  // X+10 .. X+30
    SourceLocation unknown;
    unknown.line = 99;
    follower.observe(unknown, {0.0, 0.0, 0.0});
    EXPECT_EQ(at(follower).location.line, 13u);
    follower.observe(blockOnLine(14), {25.0, 10.0, 5.0});
    EXPECT_EQ(at(follower).location.line, 14u);
    EXPECT_NEAR(follower.point().fraction, 0.25, 1e-9);  // X+30 .. X+10
    // The cycle's block lies behind: the follower does not go back to it.
    follower.observe(blockOnLine(12), {10.0, 10.0, 2.0});
    EXPECT_EQ(at(follower).location.line, 14u);
    follower.finish();
    EXPECT_EQ(follower.point().command, program.commands.size());
}

}  // namespace
}  // namespace kerf::ui
