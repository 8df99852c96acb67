// The 14xx probing family through the Klartext front end: cycle 1416's nominal positions written
// "nominal@actual" (parsed, checked at their line and column, run) and cycle 1493 PROBING
// EXTRUSION before it. The part is a 100 x 60 x 40 blank placed with shift 1.5 / -0.8 / -0.2 mm
// and 0.7 degrees; the expected values come from that geometry by hand.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/klartext/program_file.h"
#include "core/machine/machine_loader.h"
#include "core/tables/tool_table.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

const double kAngle = 0.7 * std::numbers::pi / 180.0;
// The ball (radius 2) touching a face turned by 0.7 degrees axis-parallel stops this much short.
const double kCosineError = 2.0 * (1.0 / std::cos(kAngle) - 1.0);

class NullSink : public canon::Sink {
public:
    void consume(const canon::Command&) override {}
};

// Cycle 1416 on the front-left corner (edge 1 the front face probed along +Y, edge 2 the left
// face probed along +X), or in the YZ plane at X 50 on the top-front edge; `q1100` is written as
// given.
std::string intersection(const std::string& q1100, bool yz = false) {
    return std::string("TCH PROBE 1416 PROBING INTERSECTION ~\n") + "  Q1100=" + q1100 +
           " ;1ST POINT REF AXIS ~\n" + "  Q1101=+0 ~\n" +
           (yz ? "  Q1102=+50 ~\n" : "  Q1102=-5 ~\n") + "  QS400=\"2-2\" ~\n" + "  Q1130=+0 ~\n" +
           (yz ? "  Q1131=-1 ~\n" : "  Q1131=+1 ~\n") +
           "  Q1132=+10 ~\n  Q1133=+40 ~\n  QS401=\"2-2\" ~\n  Q1134=+90 ~\n  Q1135=-1 ~\n" +
           (yz ? "  Q1136=-10 ~\n  Q1137=-30 ~\n  Q1139=+1 ~\n"
               : "  Q1136=+10 ~\n  Q1137=+40 ~\n  Q1139=+3 ~\n") +
           "  Q320=+0 ~\n  Q260=+100 ~\n  Q1125=+2 ~\n  Q309=+0 ~\n  Q1126=+0 ~\n"
           "  Q1120=+0 ~\n  Q1121=+0\n";
}

std::string extrusion(int q1149) {
    return "TCH PROBE 1493 PROBING EXTRUSION ~\n"
           "  Q1140=+1 ;DIRECTION ~\n  Q1145=+40 ;LENGTH ~\n  Q1146=+2 ;POINTS ~\n  Q1149=" +
           std::to_string(q1149) + " ;MODAL\n";
}

DiagnosticList check(const std::string& body) {
    ProgramFile program;
    program.source = program::SourceText::fromString(
        "0 BEGIN PGM P MM\n1 TOOL CALL 1 Z\n2 " + body + "3 END PGM P MM\n", "P.H");
    checkProgram(program);
    return program.diagnostics;
}

TEST(Probing14xxCheck, ActualPositionsOfTheNominalFieldsAreClean) {
    EXPECT_TRUE(check(intersection("+0@+1.5")).empty());
    EXPECT_TRUE(check(intersection("-2.5@-2.4985")).empty());
    EXPECT_TRUE(check(extrusion(0)).empty());
}

TEST(Probing14xxCheck, AnActualWhereNoneIsAllowedIsAnErrorAtItsAt) {
    // Q1102 takes one; Q1130 (line 8: "  Q1130=+0@+1 ~") does not, the '@' is its 11th column.
    std::string block = intersection("+0");
    block.replace(block.find("Q1102=-5"), 8, "Q1102=-5@-5.1");
    EXPECT_TRUE(check(block).empty());
    block = intersection("+0");
    block.replace(block.find("Q1130=+0"), 8, "Q1130=+0@+1");
    const DiagnosticList d = check(block);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].code, "cycle-parameter");
    EXPECT_EQ(d[0].line, 8u);
    EXPECT_EQ(d[0].column, 11u);
    EXPECT_EQ(d[0].message(),
              "touch probe cycle 1416: parameter Q1130 (Nominal angle of the 1st line) takes no "
              "actual position (nominal@actual is for the nominal positions of a 14xx cycle)");
}

TEST(Probing14xxCheck, AnActualOutsideTheRangeIsReportedAtItsAt) {
    const DiagnosticList d = check(intersection("+0@+100000"));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].code, "cycle-range");
    EXPECT_EQ(d[0].line, 4u);
    EXPECT_EQ(d[0].column, 11u);
}

TEST(Probing14xxCheck, UnknownNominalPositionsAreClean) {
    std::string block = intersection("?");
    block.replace(block.find("Q1101=+0"), 8, "Q1101=?");
    block.replace(block.find("Q1102=-5"), 8, "Q1102=?");
    EXPECT_TRUE(check(block).empty());
}

TEST(Probing14xxCheck, AnUnknownWhereNoneIsAllowedIsAnErrorAtItsQuestionMark) {
    // 1416's Q1130 (line 8: "  Q1130=? ~", the '?' in column 9).
    std::string block = intersection("+0");
    block.replace(block.find("Q1130=+0"), 8, "Q1130=?");
    DiagnosticList d = check(block);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].code, "cycle-parameter");
    EXPECT_EQ(d[0].line, 8u);
    EXPECT_EQ(d[0].column, 9u);
    EXPECT_EQ(d[0].message(),
              "touch probe cycle 1416: parameter Q1130 (Nominal angle of the 1st line) cannot be "
              "unknown ('?' is for the nominal positions of a 14xx cycle)");
    // A 4xx cycle's touch point and a machining cycle's parameter: line 4, after "  Q263=" (or
    // "  Q200=").
    d = check(
        "TCH PROBE 400 BASIC ROTATION\n  Q263=?\n  Q264=+0\n  Q265=+80\n  Q266=+0\n"
        "  Q272=+2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q307=0\n"
        "  Q305=0\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 4u);
    EXPECT_EQ(d[0].column, 8u);
    EXPECT_NE(d[0].message().find("Q263"), std::string::npos) << d[0].message();
    d = check(
        "CYCL DEF 200 DRILLING\n  Q200=? ;SET-UP CLEARANCE\n  Q201=-10\n  Q206=150\n"
        "  Q202=5\n  Q210=0\n  Q203=+0\n  Q204=50\n  Q211=0\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 4u);
    EXPECT_EQ(d[0].column, 8u);
    EXPECT_EQ(d[0].message().rfind("cycle 200: parameter Q200 (", 0), 0u) << d[0].message();
    EXPECT_NE(d[0].message().find(") cannot be unknown"), std::string::npos) << d[0].message();
}

class Probing14xxRun : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_probing14xx_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        machine = *machine::parseMachine(
            "base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n",
            "test.toml");
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs `blocks` (each "TCH PROBE ..." text) after the blank and the probe's TOOL CALL.
    interp::RunStatus run(const std::vector<std::string>& blocks) {
        std::string text =
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n"
            "2 BLK FORM 0.2 X+100 Y+60 Z+0\n3 TOOL CALL 1 Z\n"
            "4 L X-20 Y-20 Z+50 R0 FMAX\n";
        int n = 5;
        for (const std::string& block : blocks)
            text += std::to_string(n++) + " " + block;
        text += std::to_string(n) + " END PGM P MM\n";
        KlartextSettings settings;
        settings.machine = &machine;
        settings.tools = &tools;
        settings.ncRoot = dir;
        settings.presetInMachine = Pose{{0.0, 0.0, -400.0}};
        interpreter = std::make_unique<KlartextInterpreter>(sources, settings);
        writeFileAtomically(dir / "P.H", text);
        if (!interpreter->load(dir / "P.H")) return interp::RunStatus::Failed;
        for (;;) {
            auto status = interpreter->run(sink, 1000);
            if (status != interp::RunStatus::BudgetUsed) return status;
        }
    }
    double q(uint16_t index) const { return interpreter->parameters().get(QRef{QKind::Q, index}); }

    fs::path dir;
    machine::MachineConfig machine;
    tables::ToolTable tools = *tables::ToolTable::parse(
        "BEGIN TOOL.T MM\nT    NAME   L      R\n1    TS     +0     +2\n[END]\n");
    program::SourceRegistry sources;
    NullSink sink;
    std::unique_ptr<KlartextInterpreter> interpreter;
};

TEST_F(Probing14xxRun, TheLeftFaceGivenAsActualIsNotProbed) {
    // Q1100 = 0@1.5: the left face (probed along X) is taken at X 1.5; the front face, measured,
    // runs at y = -0.8 + (x - 1.5) tan a less the cosine error and meets X 1.5 at Y -0.8 - e.
    ASSERT_EQ(run({intersection("+0@+1.5")}), interp::RunStatus::Finished);
    EXPECT_NEAR(q(959), 1.5, 1e-6);
    EXPECT_NEAR(q(960), -0.8 - kCosineError, 1e-6);
    EXPECT_NEAR(q(956), 1.5, 1e-9);
    EXPECT_NEAR(q(986), 1.5, 1e-9);
}

TEST_F(Probing14xxRun, ExtrusionRepeatsTheTouchesOfTheNext14xxCycle) {
    // 1493 along X by 40 in 2 steps before 1416 on the top-front edge at X 50 (YZ plane): the
    // front face's deviation along its normal is 0.8 - (x - 1.5) tan a + e, largest at X 90
    // (Q972); the top face lies 0.2 low everywhere (Q970, Q971). Q1149 = 0: the second 1416 runs
    // without it.
    const double change = 0.8 - 88.5 * std::tan(kAngle) + kCosineError;
    ASSERT_EQ(run({extrusion(0), intersection("+0", true), intersection("+0", true)}),
              interp::RunStatus::Finished);
    EXPECT_NEAR(q(972), 0.0, 1e-12);
    ASSERT_EQ(run({extrusion(0), intersection("+0", true)}), interp::RunStatus::Finished);
    EXPECT_NEAR(q(970), -0.2, 1e-6);
    EXPECT_NEAR(q(971), -0.2, 1e-6);
    EXPECT_NEAR(q(972), change, 1e-6);
    // Q1149 = 1: every following 14xx cycle is extruded.
    ASSERT_EQ(run({extrusion(1), intersection("+0", true), intersection("+0", true)}),
              interp::RunStatus::Finished);
    EXPECT_NEAR(q(972), change, 1e-6);
    // A 1493 with Q1145 = 0 switches it off.
    std::string off = extrusion(1);
    off.replace(off.find("Q1145=+40"), 9, "Q1145=+0");
    ASSERT_EQ(run({extrusion(1), off, intersection("+0", true)}), interp::RunStatus::Finished);
    EXPECT_NEAR(q(972), 0.0, 1e-12);
}

}  // namespace
}  // namespace kerf::klartext
