// Probing what the program machined: the simulated part is the blank placed with the machine
// file's setup error (shift 1.5 / -0.8 / -0.2 mm, 0.7 degrees) less what the tools removed. A
// feature the program cut lies where the tool went, whatever the setup error: the values below
// are the programmed geometry.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "core/tables/tool_table.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class Discard : public canon::Sink {
public:
    void consume(const canon::Command&) override {}
};

class ProbingMachinedTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_probing_machined_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    interp::RunStatus run(const std::string& body) {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.tools = &tools;
        settings.ncRoot = dir;
        settings.presetInMachine = Pose{{0.0, 0.0, -400.0}};
        interpreter = std::make_unique<KlartextInterpreter>(sources, settings);
        writeFileAtomically(
            dir / "P.H", "0 BEGIN PGM P MM\n" + std::string(kBlank) + body + "99 END PGM P MM\n");
        if (!interpreter->load(dir / "P.H")) return interp::RunStatus::Failed;
        for (;;) {
            auto status = interpreter->run(out, 1000);
            if (status != interp::RunStatus::BudgetUsed) return status;
        }
    }
    double q(uint16_t index) const { return interpreter->parameters().get(QRef{QKind::Q, index}); }
    std::string firstError() const {
        for (const Diagnostic& d : interpreter->diagnostics())
            if (d.severity == Severity::Error) return d.code + ": " + d.format();
        return {};
    }

    // A 100 x 60 x 40 block, top at Z 0; the D10 end mill (tool 5) in the spindle above it.
    static constexpr const char* kBlank =
        "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
        "3 TOOL CALL 5 Z S3000\n4 L Z+100 R0 FMAX M3\n";

    fs::path dir;
    machine::MachineConfig machine = *machine::parseMachine(
        "base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n",
        "test.toml");
    // The probe (TP_NO: a touch probe, it cuts nothing) with a ball of radius 2, a D10 end mill,
    // a D10 ball-nose end mill (plunge angle 30 degrees for the helical plunge of 252).
    tables::ToolTable tools = *tables::ToolTable::parse(
        "BEGIN TOOL.T MM\nT    NAME   L      R      R2     ANGLE  TP_NO\n"
        "1    TS     +50    +2     +0     +0     1\n"
        "5    D10    +80    +5     +0     +30\n"
        "6    BALL10 +80    +5     +5     +30\n[END]\n");
    program::SourceRegistry sources;
    Discard out;
    std::unique_ptr<KlartextInterpreter> interpreter;
};

TEST_F(ProbingMachinedTest, HoleDrilledByCycle200IsFoundBy412) {
    // A D10 hole at (30, 20), 15 deep; 412 probes it from its centre at Z -5.
    ASSERT_EQ(run("5 CYCL DEF 200 DRILLING\n  Q200=2\n  Q201=-15\n  Q206=250\n  Q202=5\n"
                  "  Q210=0\n  Q203=+0\n  Q204=20\n  Q211=0\n  Q395=0\n"
                  "6 L X+30 Y+20 R0 FMAX M99\n7 L Z+100 R0 FMAX\n8 TOOL CALL 1 Z\n"
                  "9 TCH PROBE 412 DATUM INSIDE CIRCLE\n  Q321=+30\n  Q322=+20\n  Q262=10\n"
                  "  Q325=+0\n  Q247=+90\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=0\n"
                  "  Q305=0\n  Q331=+30\n  Q332=+20\n  Q303=+1\n  Q381=0\n  Q382=+0\n"
                  "  Q383=+0\n  Q384=+0\n  Q333=+0\n  Q423=4\n  Q365=1\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(151), 30.0, 0.002);
    EXPECT_NEAR(q(152), 20.0, 0.002);
    EXPECT_NEAR(q(153), 10.0, 0.002);
}

TEST_F(ProbingMachinedTest, WithoutTheHoleTheProbeTouchesMaterialAtOnce) {
    // The same 412 on the blank as it is: the ball at Z -5 sits in material (PRB-002).
    EXPECT_EQ(run("5 L Z+100 R0 FMAX\n6 TOOL CALL 1 Z\n"
                  "7 TCH PROBE 412 DATUM INSIDE CIRCLE\n  Q321=+30\n  Q322=+20\n  Q262=10\n"
                  "  Q325=+0\n  Q247=+90\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=0\n"
                  "  Q305=0\n  Q331=+30\n  Q332=+20\n  Q303=+1\n  Q381=0\n  Q382=+0\n"
                  "  Q383=+0\n  Q384=+0\n  Q333=+0\n  Q423=4\n  Q365=1\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-"), std::string::npos) << firstError();
}

const char* kMeasureHole40 =
    "  Q273=+50\n  Q274=+30\n  Q262=40\n  Q325=+0\n  Q247=+90\n  Q261=-5\n  Q320=0\n"
    "  Q260=+20\n  Q301=1\n  Q275=0\n  Q276=0\n  Q279=0\n  Q280=0\n  Q281=0\n  Q309=0\n"
    "  Q330=0\n  Q423=4\n  Q365=1\n";

TEST_F(ProbingMachinedTest, CircularPocket252IsMeasuredBy421) {
    // A pocket of diameter 40 at (50, 30), 10 deep, plunged helically: its finishing circle
    // puts the wall at radius 20 exactly.
    ASSERT_EQ(run("5 CYCL DEF 252 CIRCULAR POCKET\n  Q215=0\n  Q223=40\n  Q368=0\n  Q207=500\n"
                  "  Q351=+1\n  Q201=-10\n  Q202=5\n  Q369=0\n  Q206=150\n  Q338=0\n"
                  "  Q200=2\n  Q203=+0\n  Q204=20\n  Q370=1\n  Q366=1\n  Q385=300\n"
                  "  Q439=0\n"
                  "6 L X+50 Y+30 R0 FMAX M99\n7 L Z+100 R0 FMAX\n8 TOOL CALL 1 Z\n"
                  "9 TCH PROBE 421 MEASURE HOLE\n" +
                  std::string(kMeasureHole40)),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(151), 50.0, 0.002);
    EXPECT_NEAR(q(152), 30.0, 0.002);
    EXPECT_NEAR(q(153), 40.0, 0.002);
    EXPECT_NEAR(q(163), 0.0, 0.002);  // the diameter's deviation
}

TEST_F(ProbingMachinedTest, BallNoseCutterLeavesTheSameWallAboveItsRoundedBottom) {
    // The pocket cut with the ball-nose D10 (R2 = 5): the wall at radius 20 is straight from
    // 5 above the floor up, so 421 at Z -5 (5 above the floor at -10) finds it unchanged.
    ASSERT_EQ(run("5 TOOL CALL 6 Z S3000\n"
                  "6 CYCL DEF 252 CIRCULAR POCKET\n  Q215=0\n  Q223=40\n  Q368=0\n  Q207=500\n"
                  "  Q351=+1\n  Q201=-10\n  Q202=5\n  Q369=0\n  Q206=150\n  Q338=0\n"
                  "  Q200=2\n  Q203=+0\n  Q204=20\n  Q370=1\n  Q366=1\n  Q385=300\n"
                  "  Q439=0\n"
                  "7 L X+50 Y+30 R0 FMAX M99\n8 L Z+100 R0 FMAX\n9 TOOL CALL 1 Z\n"
                  "10 TCH PROBE 421 MEASURE HOLE\n" +
                  std::string(kMeasureHole40)),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(153), 40.0, 0.002);
}

TEST_F(ProbingMachinedTest, CircularStud257IsMeasuredBy422) {
    // A stud of diameter 30 at (50, 30) from a blank diameter of 50, 10 deep.
    ASSERT_EQ(run("5 CYCL DEF 257 CIRCULAR STUD\n  Q223=30\n  Q222=50\n  Q368=0\n  Q207=500\n"
                  "  Q351=+1\n  Q201=-10\n  Q202=5\n  Q206=150\n  Q200=2\n  Q203=+0\n"
                  "  Q204=20\n  Q370=1\n  Q376=+0\n"
                  "6 L X+50 Y+30 R0 FMAX M99\n7 L Z+100 R0 FMAX\n8 TOOL CALL 1 Z\n"
                  "9 TCH PROBE 422 MEASURE CIRCLE OUTSIDE\n  Q273=+50\n  Q274=+30\n"
                  "  Q262=30\n  Q325=+0\n  Q247=+90\n  Q261=-5\n  Q320=0\n  Q260=+20\n"
                  "  Q301=1\n  Q275=0\n  Q276=0\n  Q279=0\n  Q280=0\n  Q281=0\n  Q309=0\n"
                  "  Q330=0\n  Q423=4\n  Q365=1\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(151), 50.0, 0.002);
    EXPECT_NEAR(q(152), 30.0, 0.002);
    EXPECT_NEAR(q(153), 30.0, 0.002);
}

TEST_F(ProbingMachinedTest, Slot253IsMeasuredBy425AndItsFloorBy417) {
    // A slot 40 long and 16 wide along X, centred at (50, 30), 10 deep: 425 across it (Y)
    // from its centre, 417 on its floor.
    ASSERT_EQ(run("5 CYCL DEF 253 SLOT MILLING\n  Q215=0\n  Q218=40\n  Q219=16\n  Q368=0\n"
                  "  Q374=+0\n  Q367=0\n  Q207=500\n  Q351=+1\n  Q201=-10\n  Q202=5\n"
                  "  Q369=0\n  Q206=150\n  Q338=0\n  Q200=2\n  Q203=+0\n  Q204=20\n"
                  "  Q366=0\n  Q385=300\n  Q439=0\n"
                  "6 L X+50 Y+30 R0 FMAX M99\n7 L Z+100 R0 FMAX\n8 TOOL CALL 1 Z\n"
                  "9 TCH PROBE 425 MEASURE INSIDE WIDTH\n  Q328=+50\n  Q329=+30\n  Q310=+0\n"
                  "  Q272=2\n  Q261=-5\n  Q260=+20\n  Q311=16\n  Q288=0\n  Q289=0\n"
                  "  Q281=0\n  Q309=0\n  Q330=0\n  Q320=0\n  Q301=1\n"
                  "10 TCH PROBE 417 DATUM IN TS AXIS\n  Q263=+50\n  Q264=+30\n  Q294=-10\n"
                  "  Q320=0\n  Q260=+20\n  Q305=0\n  Q333=-10\n  Q303=+1\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(156), 16.0, 0.002);  // the width
    EXPECT_NEAR(q(157), 30.0, 0.002);  // its centre line
    EXPECT_NEAR(q(160), -10.0, 0.002);
}

TEST_F(ProbingMachinedTest, TwoDrilledHolesTurnTheCTableWith401) {
    // Seed example 13.8 after drilling its holes: (25, 15) and (80, 35) where the tool went,
    // so the line between them lies at atan2(20, 55) whatever the setup error; Q402 = 1 turns
    // the C table of mill5 by that (Q307 = 0), Q337 = 0 leaves its display.
    machine = *machine::parseMachine(
        "base = \"mill5\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n",
        "test.toml");
    ASSERT_EQ(run("5 L C+0 R0 FMAX\n"
                  "6 CYCL DEF 200 DRILLING\n  Q200=2\n  Q201=-15\n  Q206=250\n  Q202=5\n"
                  "  Q210=0\n  Q203=+0\n  Q204=20\n  Q211=0\n  Q395=0\n"
                  "7 L X+25 Y+15 R0 FMAX M99\n8 L X+80 Y+35 R0 FMAX M99\n9 L Z+100 R0 FMAX\n"
                  "10 TOOL CALL 1 Z\n"
                  "11 TCH PROBE 401 ROT OF 2 HOLES\n  Q268=+25\n  Q269=+15\n  Q270=+80\n"
                  "  Q271=+35\n  Q261=-5\n  Q260=+20\n  Q307=+0\n  Q305=0\n  Q402=1\n"
                  "  Q337=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::C],
                std::atan2(20.0, 55.0) * 180.0 / std::numbers::pi, 0.002);
}

}  // namespace
}  // namespace kerf::klartext
