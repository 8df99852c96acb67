// TCH PROBE cycles through the Klartext interpreter: the simulated part is the program's blank
// placed with the machine file's setup error (shift 1.5 / -0.8 / -0.2 mm, 0.7 degrees).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "core/tables/datum_table.h"
#include "core/tables/preset_table.h"
#include "core/tables/probe_table.h"
#include "core/tables/tool_table.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class Recorder : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
};

class ProbingTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_probing_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        machine = *machine::parseMachine(
            "base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n",
            "test.toml");
        tools = *tables::ToolTable::parse(
            "BEGIN TOOL.T MM\nT    NAME   L      R\n"
            "1    TS     +0     +2\n[END]\n");
    }
    void TearDown() override { fs::remove_all(dir); }
    void useMachine(const std::string& toml) {
        machine = *machine::parseMachine(toml, "test.toml");
    }

    interp::RunStatus run(const std::string& body) {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.tools = &tools;
        settings.ncRoot = dir;
        settings.presetInMachine = presetInMachine;
        settings.basicRotationDeg = basicRotationDeg;
        interpreter = std::make_unique<KlartextInterpreter>(sources, settings);
        writeFileAtomically(dir / "P.H", "0 BEGIN PGM P MM\n" + body + "99 END PGM P MM\n");
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

    fs::path dir;
    // The start preset, machine coordinates: the built-in mill's (axes.Z.preset = -400).
    Pose presetInMachine{{0.0, 0.0, -400.0}};
    double basicRotationDeg = 0.0;  // the preset's SPC
    machine::MachineConfig machine;
    tables::ToolTable tools = *tables::ToolTable::parse("BEGIN TOOL.T MM\nT\n[END]\n");
    program::SourceRegistry sources;
    Recorder out;
    std::unique_ptr<KlartextInterpreter> interpreter;
};

const char* kStudAndDatum =
    "1 BLK FORM CYLINDER Z R25 L30 DIST+0\n"
    "2 TOOL CALL 1 Z\n"
    "3 L X+0 Y+0 Z+50 R0 FMAX\n"
    "4 TCH PROBE 413 DATUM OUTSIDE CIRCLE\n"
    "  Q321=+0 ;CENTER IN 1ST AXIS\n  Q322=+0\n  Q262=52\n  Q325=+0\n  Q247=+90\n"
    "  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q305=0\n  Q331=+0\n  Q332=+0\n"
    "  Q303=+1\n  Q381=1\n  Q382=+0\n  Q383=+0\n  Q384=+0\n  Q333=+0\n  Q423=4\n  Q365=1\n";

TEST_F(ProbingTest, DatumOutsideCircleSetsThePresetAtTheRealStud) {
    ASSERT_EQ(run(std::string(kStudAndDatum) + "5 L X+0 Y+0 Z+10 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(151), 1.5, 1e-6);
    EXPECT_NEAR(q(152), -0.8, 1e-6);
    EXPECT_NEAR(q(153), 50.0, 1e-6);
    // The status shows the last touch, on the top: the tool tip (the ball's south pole) rests
    // on the real top at -0.2.
    const auto probe = interpreter->programStatus().probe;
    ASSERT_TRUE(probe && probe->triggered);
    EXPECT_NEAR(probe->position[Axis::Z], -0.2, 1e-6);
    // The next move to X0 Y0 Z10 goes to the real stud centre, 10 above its real top.
    const Pose end = interpreter->nominalPosition();
    EXPECT_NEAR(end[Axis::X], 1.5, 1e-6);
    EXPECT_NEAR(end[Axis::Y], -0.8, 1e-6);
    EXPECT_NEAR(end[Axis::Z], 9.8, 1e-6);
    // Q305 = 0 also stores the datum in row 0 of the preset table, in machine coordinates
    // (the start preset lies at machine Z -400).
    auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets.ok());
    const tables::PresetData* row0 = presets->byNumber(0);
    ASSERT_NE(row0, nullptr);
    EXPECT_NEAR(*row0->axis('X'), 1.5, 1e-4);
    EXPECT_NEAR(*row0->axis('Y'), -0.8, 1e-4);
    EXPECT_NEAR(*row0->axis('Z'), -400.2, 1e-4);
}

TEST_F(ProbingTest, BasicRotationAndTwoEdgesMakeTheCornerTheDatum) {
    // After cycle 400 the program frame is turned by the 0.7 degrees the part is turned, so the
    // part lies square in it, shifted by s' = R(-0.7 deg) (1.5, -0.8): the left face at
    // x = s'.x, the front face at y = s'.y. 419 sets each as the datum; 426 then measures the
    // 100 mm width square to the faces, its centre line at X 50.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double sx = 1.5 * std::cos(a) - 0.8 * std::sin(a);
    const double sy = -1.5 * std::sin(a) - 0.8 * std::cos(a);
    const std::string program =
        "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
        "3 TOOL CALL 1 Z\n4 L X-10 Y-10 Z+50 R0 FMAX\n"
        "5 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+60\n"
        "  Q266=+0\n  Q272=2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n"
        "  Q301=1\n  Q307=0\n  Q305=0\n"
        "6 TCH PROBE 419 DATUM IN ONE AXIS\n  Q263=+0\n  Q264=+30\n  Q261=-5\n"
        "  Q320=0\n  Q260=+20\n  Q272=1\n  Q267=+1\n  Q305=0\n  Q333=+0\n  Q303=+1\n"
        "7 Q10 = Q160\n"
        "8 TCH PROBE 419 DATUM IN ONE AXIS\n  Q263=+50\n  Q264=+0\n  Q261=-5\n"
        "  Q320=0\n  Q260=+20\n  Q272=2\n  Q267=+1\n  Q305=0\n  Q333=+0\n  Q303=+1\n"
        "9 Q11 = Q160\n"
        "10 TCH PROBE 426 MEASURE RIDGE WIDTH\n  Q328=+50\n  Q329=+30\n  Q310=+0\n"
        "  Q272=1\n  Q261=-5\n  Q260=+20\n  Q311=100\n  Q288=100.01\n  Q289=99.99\n"
        "  Q281=1\n  Q309=0\n  Q330=0\n  Q320=0\n  Q301=1\n";
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(q(10), sx, 1e-6);
    EXPECT_NEAR(q(11), sy, 1e-6);
    EXPECT_NEAR(q(156), 100.0, 1e-6);
    EXPECT_NEAR(q(157), 50.0, 1e-6);
    EXPECT_NEAR(q(166), 0.0, 1e-6);
    EXPECT_EQ(q(180), 1.0);
    auto log = readWholeFile(dir / "TCHPR426.TXT");
    ASSERT_TRUE(log.ok());
    EXPECT_EQ(*log,
              "Measuring log for probing cycle 426 MEASURE RIDGE WIDTH\n"
              "Measuring program: P.H\n"
              "Nominal values:\n"
              "  length                    +100.0000\n"
              "Given limits:\n"
              "  max. length               +100.0100\n"
              "  min. length               +99.9900\n"
              "Actual values:\n"
              "  length                    +100.0000\n"
              "  centre line               +50.0000\n"
              "Deviations:\n"
              "  length                    +0.0000\n"
              "Further measuring results:\n"
              "  measuring height          -5.0000\n"
              "End of measuring log\n");
}

TEST_F(ProbingTest, RidgeCentre409MakesTheRealCentreLineTheDatum) {
    // The blank is a ridge 100 wide along X; measured along X at Y 30, its real centre line
    // crosses there at c.x - (30 - c.y) tan a with c the placed centre (50, 30), as for 425.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double cx = 50.0 * std::cos(a) - 30.0 * std::sin(a) + 1.5;
    const double cy = 50.0 * std::sin(a) + 30.0 * std::cos(a) - 0.8;
    ASSERT_EQ(run("1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
                  "3 TOOL CALL 1 Z\n4 L X+50 Y+30 Z+50 R0 FMAX\n"
                  "5 TCH PROBE 409 RIDGE CENTER REF PT\n  Q321=+50\n  Q322=+30\n  Q311=100\n"
                  "  Q272=1\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q305=0\n  Q405=+0\n"
                  "  Q303=+1\n  Q381=0\n  Q382=+0\n  Q383=+0\n  Q384=+0\n  Q333=+0\n"
                  "6 L X+0 Y+30 Z+10 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double line = cx - (30.0 - cy) * std::tan(a);
    EXPECT_NEAR(q(157), line, 1e-6);
    const Pose end = interpreter->nominalPosition();
    EXPECT_NEAR(end[Axis::X], line, 1e-6);
    EXPECT_NEAR(end[Axis::Y], 30.0, 1e-9);  // only the measuring axis moves
}

TEST_F(ProbingTest, ErrorsOfTheManual) {
    // Probing needs the probe called first.
    EXPECT_EQ(run("1 BLK FORM CYLINDER Z R25 L30 DIST+0\n"
                  "2 TCH PROBE 417 DATUM IN TS AXIS\n  Q263=+0\n  Q264=+0\n  Q294=+0\n"
                  "  Q320=0\n  Q260=+20\n  Q305=0\n  Q333=+0\n  Q303=+1\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-012"), std::string::npos) << firstError();
    // A touch that finds nothing: beside the (default simulated) blank.
    EXPECT_EQ(run("1 TOOL CALL 1 Z\n2 L Z+50 R0 FMAX\n"
                  "3 TCH PROBE 417 DATUM IN TS AXIS\n  Q263=-50\n  Q264=+0\n  Q294=+0\n"
                  "  Q320=0\n  Q260=+20\n  Q305=0\n  Q333=+0\n  Q303=+1\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-001"), std::string::npos) << firstError();
    // A probing cycle Kerf does not have is refused before the program starts.
    EXPECT_EQ(run("1 TCH PROBE 499 UNKNOWN\n  Q263=+0\n"), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("not supported"), std::string::npos) << firstError();
    // Out-of-range values are found by the check, at their line.
    EXPECT_EQ(run("1 TOOL CALL 1 Z\n2 TCH PROBE 419 DATUM IN ONE AXIS\n  Q272=7\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("P.H:3:"), std::string::npos) << firstError();
}

const char* kPlateProgram =
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
    "3 TOOL CALL 1 Z\n4 L X-10 Y-10 Z+50 R0 FMAX\n";

std::string probe403(int axis, int zero, int row, int transfer) {
    return "TCH PROBE 403 ROT IN ROTARY AXIS\n  Q263=+10\n  Q264=+0\n  Q265=+60\n  Q266=+0\n"
           "  Q272=" +
           std::to_string(axis) +
           "\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n"
           "  Q301=1\n  Q312=0\n  Q337=" +
           std::to_string(zero) + "\n  Q305=" + std::to_string(row) +
           "\n  Q303=" + std::to_string(transfer) + "\n  Q380=+0\n";
}

TEST_F(ProbingTest, Cycle403TurnsTheCTableByTheMisalignment) {
    // mill5: the C table (nearest to the workpiece) turns about the pivot, which is the preset
    // (machine 0, 0, -400). The front face is turned by the setup's 0.7 degrees: C turns by +0.7
    // (a table at angle t turns the part by -t), after which a second 403 finds the face square.
    useMachine("base = \"mill5\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n");
    ASSERT_EQ(run(std::string(kPlateProgram) + "5 " + probe403(2, 0, 0, 1) + "6 Q10 = Q150\n7 " +
                  probe403(2, 0, 0, 1) + "8 Q11 = Q150\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(10), 0.7, 1e-9);
    EXPECT_NEAR(q(11), 0.0, 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::C], 0.7, 1e-9);
}

TEST_F(ProbingTest, Cycle403SetsTheTurnedAxisToZeroInThePreset) {
    useMachine("base = \"mill5\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n");
    ASSERT_EQ(run(std::string(kPlateProgram) + "5 " + probe403(2, 1, 0, 1) + "6 L C+0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    // The C axis stands at machine 0.7 and shows 0 (C+0 stays there); preset row 0 holds 0.7.
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::C], 0.7, 1e-9);
    auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets.ok());
    ASSERT_NE(presets->byNumber(0), nullptr);
    EXPECT_NEAR(*presets->byNumber(0)->axis('C'), 0.7, 1e-4);
}

TEST_F(ProbingTest, Cycle403LevelsTheTopFaceWithTheATable) {
    // mill4: after L A+2 the table turns the part by -2 degrees about X: the top face falls by
    // tan 2 deg per mm of +Y. Touches along -Z at Y 10 and Y 50 see that slope, so 403 measures
    // -2 degrees about A and turns A back to 0 (the ball stands r_b / cos 2 deg above the face
    // at both touches, which leaves the slope exact).
    useMachine("base = \"mill4\"\n");
    ASSERT_EQ(run(std::string(kPlateProgram) +
                  "5 L A+2 FMAX\n"
                  "6 TCH PROBE 403 ROT IN ROTARY AXIS\n  Q263=+50\n  Q264=+10\n  Q265=+50\n"
                  "  Q266=+50\n  Q272=3\n  Q267=+1\n  Q261=+0\n  Q320=0\n  Q260=+20\n  Q301=1\n"
                  "  Q312=0\n  Q337=0\n  Q305=0\n  Q303=1\n  Q380=+0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(150), -2.0, 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::A], 0.0, 1e-9);
}

TEST_F(ProbingTest, Cycle403NeedsTheRightRotaryAxis) {
    // A turn about the tool axis cannot be compensated by mill4's A table, nor on a 3-axis mill.
    useMachine("base = \"mill4\"\n");
    EXPECT_EQ(run(std::string(kPlateProgram) + "5 " + probe403(2, 0, 0, 1)),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-011"), std::string::npos) << firstError();
    useMachine("base = \"mill\"\n");
    EXPECT_EQ(run(std::string(kPlateProgram) + "5 " + probe403(2, 0, 0, 1)),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-011"), std::string::npos) << firstError();
}

TEST_F(ProbingTest, Cycle405TurnsTheHoleOntoItsNominalAngle) {
    // A tube (bore 16) whose centre really lies at (1, 29): nominal (0, 30) is at 90 degrees,
    // the real centre at atan2(29, 1). C turns the part by the difference, so a second 405
    // finds nothing left to turn; the C display is then zeroed (Q337 = 0).
    useMachine("base = \"mill5\"\n[simulation.setup]\nshift = [1.0, 29.0, 0.0]\nrotation = 0.0\n");
    const std::string probe405 =
        "TCH PROBE 405 ROT IN C AXIS\n  Q321=+0\n  Q322=+30\n  Q262=16\n  Q325=+0\n"
        "  Q247=90\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=0\n  Q337=0\n";
    ASSERT_EQ(run("1 BLK FORM CYLINDER Z R20 RI8 L30 DIST+0\n2 TOOL CALL 1 Z\n"
                  "3 L X+0 Y+30 Z+50 R0 FMAX\n4 " +
                  probe405 + "5 Q10 = Q150\n6 " + probe405 + "7 Q11 = Q150\n8 L C+0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double expected = 90.0 - std::atan2(29.0, 1.0) * 180.0 / std::numbers::pi;
    EXPECT_NEAR(q(10), expected, 1e-9);
    EXPECT_NEAR(q(11), 0.0, 1e-9);
    // The table turned by -Q150; C+0 stays there.
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::C], -expected, 1e-9);
    auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets.ok());
    EXPECT_NEAR(*presets->byNumber(0)->axis('C'), -expected, 1e-4);
}

TEST_F(ProbingTest, Cycle404SetsAndClearsTheBasicRotation) {
    // 404 turns the working plane about the datum; Q307 = 0 clears it; Q305 = 3 stores 5 degrees
    // in the SPC column of preset row 3 without turning anything.
    writeFileAtomically(dir / "PRESET.PR",
                        "BEGIN PRESET.PR MM\nNR   DOC   X        Y        Z        SPC\n"
                        "0          +0       +0       +0       +0\n[END]\n");
    const double a = 5.0 * std::numbers::pi / 180.0;
    ASSERT_EQ(run("1 TOOL CALL 1 Z\n"
                  "2 TCH PROBE 404 SET BASIC ROTATION\n  Q307=+5\n  Q305=-1\n"
                  "3 L X+10 Y+0 Z+50 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 10.0 * std::cos(a), 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], 10.0 * std::sin(a), 1e-9);
    ASSERT_EQ(run("1 TOOL CALL 1 Z\n"
                  "2 TCH PROBE 404 SET BASIC ROTATION\n  Q307=+5\n  Q305=-1\n"
                  "3 TCH PROBE 404 SET BASIC ROTATION\n  Q307=+0\n  Q305=0\n"
                  "4 TCH PROBE 404 SET BASIC ROTATION\n  Q307=+5\n  Q305=3\n"
                  "5 L X+10 Y+0 Z+50 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 10.0, 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], 0.0, 1e-9);
    auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets.ok());
    const tables::PresetData* row3 = presets->byNumber(3);
    ASSERT_NE(row3, nullptr);
    auto spc = presets->table().findColumn("SPC");
    ASSERT_TRUE(spc);
    EXPECT_EQ(presets->table().number(row3->row, *spc), 5.0);
}

TEST_F(ProbingTest, FreshNcRootStoresTheBasicRotationInTheDefaultPresetTable) {
    // No PRESET.PR yet: the table Kerf creates has the SPC column, so 400 with Q305 = 2 stores
    // the part's real 0.7 degrees there (the front face from X10 to X60, Q272 = 1), without
    // turning the working plane.
    ASSERT_FALSE(fs::exists(dir / "PRESET.PR"));
    ASSERT_EQ(run("1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
                  "3 TOOL CALL 1 Z\n4 L X-10 Y-10 Z+50 R0 FMAX\n"
                  "5 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+60\n"
                  "  Q266=+0\n  Q272=2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n"
                  "  Q301=1\n  Q307=0\n  Q305=2\n"
                  "6 L X+10 Y+0 Z+50 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 10.0, 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], 0.0, 1e-9);
    auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets.ok());
    const tables::PresetData* row2 = presets->byNumber(2);
    ASSERT_NE(row2, nullptr);
    auto spc = presets->table().findColumn("SPC");
    ASSERT_TRUE(spc);
    EXPECT_NEAR(presets->table().number(row2->row, *spc).value_or(0.0), 0.7, 1e-4);
}

TEST_F(ProbingTest, OlderPresetTableWithoutSpcGetsTheColumn) {
    // A preset table from an older control: X Y Z only, CRLF, a second preset. 400 with
    // Q305 = 0 keeps the part's real 0.7 degrees in row 0: the table gets an SPC column for it
    // and keeps everything else.
    const std::string older =
        "BEGIN PRESET.PR MM\r\n"
        "NR   DOC          X          Y          Z\r\n"
        "0                 +0         +0         -400\r\n"
        "1    vice         +120.5     -35.125    +200\r\n"
        "[END]\r\n";
    writeFileAtomically(dir / "PRESET.PR", older);
    ASSERT_EQ(run("1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
                  "3 TOOL CALL 1 Z\n4 L X-10 Y-10 Z+50 R0 FMAX\n"
                  "5 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+60\n"
                  "  Q266=+0\n  Q272=2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n"
                  "  Q301=1\n  Q307=0\n  Q305=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets.ok()) << presets.error().format();
    EXPECT_NEAR(presets->basicRotationDeg(0), 0.7, 1e-4);
    EXPECT_EQ(presets->basicRotationDeg(1), 0.0);
    const std::string written = presets->serialize();
    // The old header and rows stay as they were up to the new column, line endings included.
    EXPECT_EQ(
        written.rfind("BEGIN PRESET.PR MM\r\nNR   DOC          X          Y          Z    SPC", 0),
        0u);
    EXPECT_NE(written.find("\r\n1    vice         +120.5     -35.125    +200\r\n[END]\r\n"),
              std::string::npos);
    EXPECT_EQ(*presets->byNumber(0)->axis('Z'), -400.0);
}

TEST_F(ProbingTest, DatumCycleWritesTheDatumTableWithQ303Zero) {
    // 413 with Q303 = 0, Q305 = 2: row 2 of the datum table selected with SEL TABLE gets the
    // shift that gives the real stud centre (1.5, -0.8) and its top (-0.2) the nominal 0.
    writeFileAtomically(dir / "ZERO.D",
                        "BEGIN ZERO.D MM\nD    X         Y         Z         DOC\n"
                        "0    +0        +0        +0\n[END]\n");
    std::string program(kStudAndDatum);
    program.replace(program.find("Q305=0"), 6, "Q305=2");
    program.replace(program.find("Q303=+1"), 7, "Q303=+0");
    ASSERT_EQ(run("0 SEL TABLE \"ZERO.D\"\n" + program), interp::RunStatus::Finished)
        << firstError();
    auto datums = tables::DatumTable::load(dir / "ZERO.D");
    ASSERT_TRUE(datums.ok());
    const tables::DatumData* row2 = datums->byNumber(2);
    ASSERT_NE(row2, nullptr);
    EXPECT_NEAR(*row2->axis('X'), 1.5, 1e-4);
    EXPECT_NEAR(*row2->axis('Y'), -0.8, 1e-4);
    EXPECT_NEAR(*row2->axis('Z'), -0.2, 1e-4);
    // The active preset is left alone.
    EXPECT_FALSE(fs::exists(dir / "PRESET.PR"));
}

std::string probe444(const std::string& point, const std::string& normal,
                     const std::string& tolerance, int reaction) {
    return "TCH PROBE 444 PROBING IN 3-D\n" + point + normal + "  Q320=+0\n  Q260=+20\n" +
           "  QS400=\"" + tolerance + "\"\n  Q309=" + std::to_string(reaction) + "\n";
}

TEST_F(ProbingTest, Cycle444ChecksAPointAlongItsNormal) {
    // The top face really lies at Z -0.2: the point (50, 30, 0) with normal +Z is 0.2 under
    // size, within "0.5-0.3" (good). On the left face (normal -X) at Y 30 the real face lies at
    // x = 1.5 - 30.8 tan a (a = 0.7 deg, the face turned about the shifted origin), seen r_b
    // (1/cos a - 1) nearer by an axis-parallel ball; 444 probes along +X, so the point is that
    // far inside: undersize, beyond -0.1 (scrap, Q309 = 0 keeps running).
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double face = 1.5 - 30.8 * std::tan(a) - 2.0 * (1.0 / std::cos(a) - 1.0);
    ASSERT_EQ(run(std::string(kPlateProgram) + "5 " +
                  probe444("  Q263=+50\n  Q264=+30\n  Q294=+0\n",
                           "  Q581=+0\n  Q582=+0\n  Q583=+2\n", "0.5-0.3", 1) +
                  "6 Q10 = Q164\n7 Q11 = Q183\n8 Q12 = Q153\n9 " +
                  probe444("  Q263=+0\n  Q264=+30\n  Q294=-5\n",
                           "  Q581=-1\n  Q582=+0\n  Q583=+0\n", "0.5-0.1", 0)),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(10), -0.2, 1e-9);
    EXPECT_EQ(q(11), 0.0);
    EXPECT_NEAR(q(12), -0.2, 1e-9);
    EXPECT_NEAR(q(151), face, 1e-9);
    EXPECT_NEAR(q(152), 30.0, 1e-9);
    EXPECT_NEAR(q(153), -5.0, 1e-9);
    EXPECT_NEAR(q(161), face, 1e-9);
    EXPECT_NEAR(q(164), -face, 1e-9);
    EXPECT_EQ(q(183), 2.0);
    EXPECT_TRUE(fs::exists(dir / "TCHPR444.TXT"));
    // Q309 = 2 stops on undersize; "0.1+0.1" is no tolerance at all (good).
    EXPECT_EQ(run(std::string(kPlateProgram) + "5 " +
                  probe444("  Q263=+0\n  Q264=+30\n  Q294=-5\n",
                           "  Q581=-1\n  Q582=+0\n  Q583=+0\n", "0.5-0.1", 2)),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-006"), std::string::npos) << firstError();
    ASSERT_EQ(run(std::string(kPlateProgram) + "5 " +
                  probe444("  Q263=+0\n  Q264=+30\n  Q294=-5\n",
                           "  Q581=-1\n  Q582=+0\n  Q583=+0\n", "0.1+0.1", 2)),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(q(183), 0.0);
}

TEST_F(ProbingTest, Cycle441SetsThePositioningFeedAndTracking) {
    // After 441 the positioning moves run at Q396 instead of rapid (the default probe table
    // pre-positions at FMAX 3000), and each touch in the plane orients the spindle to its
    // direction first (Q399 = 1): 413's four touches inward at 180, -90, 0 and 90 degrees.
    ASSERT_EQ(run("1 BLK FORM CYLINDER Z R25 L30 DIST+0\n2 TOOL CALL 1 Z\n"
                  "3 L X+0 Y+0 Z+50 R0 FMAX\n"
                  "4 TCH PROBE 441 FAST PROBING\n  Q396=1234\n  Q397=0\n  Q399=1\n  Q400=0\n"
                  "5 TCH PROBE 413 DATUM OUTSIDE CIRCLE\n"
                  "  Q321=+0\n  Q322=+0\n  Q262=52\n  Q325=+0\n  Q247=+90\n"
                  "  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q305=0\n  Q331=+0\n  Q332=+0\n"
                  "  Q303=+1\n  Q381=0\n  Q382=+0\n  Q383=+0\n  Q384=+0\n  Q333=+0\n  Q423=4\n"
                  "  Q365=1\n"),
              interp::RunStatus::Finished)
        << firstError();
    std::vector<double> orientations;
    size_t feeds = 0;
    for (const canon::Command& c : out.commands) {
        if (const auto* o = std::get_if<canon::SpindleOrient>(&c.body)) {
            orientations.push_back(o->angleDeg);
        }
        if (const auto* m = std::get_if<canon::LinearMove>(&c.body)) feeds += m->feed == 1234.0;
    }
    ASSERT_EQ(orientations.size(), 4u);
    EXPECT_NEAR(orientations[0], 180.0, 1e-9);
    EXPECT_NEAR(orientations[1], -90.0, 1e-9);
    EXPECT_NEAR(orientations[2], 0.0, 1e-9);
    EXPECT_NEAR(orientations[3], 90.0, 1e-9);
    EXPECT_GT(feeds, 0u);
}

// The probe (tool 1, L 0 R 2 in the table) is really 0.1 longer with a ball 0.02 smaller.
const char* kProbeError =
    "base = \"mill\"\n[simulation.setup]\nshift = [0.5, -0.3, 0.0]\nrotation = 0.0\n"
    "[[simulation.tool_error]]\ntool = 1\nlength = 0.1\nradius = -0.02\n";

TEST_F(ProbingTest, Cycle461CalibratesTheProbeLengthOnTheTopFace) {
    // The top face lies at Z 0 = Q434: the real tip touches it when the gauge point stands at
    // 0.1, so L becomes 0.1 and takes effect at once (Q114).
    useMachine(kProbeError);
    ASSERT_EQ(run(std::string(kPlateProgram) + "5 L X+50 Y+30 Z+10 FMAX\n"
                                               "6 TCH PROBE 461 CALIBRATE TS LENGTH\n  Q434=+0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(114), 0.1, 1e-9);
    auto written = tables::ToolTable::load(dir / "TOOL.T");
    ASSERT_TRUE(written.ok());
    EXPECT_NEAR(written->byNumber(1)->length, 0.1, 1e-4);
}

// The tube's bore of radius 5 as a calibration ring, the probe in it at Z-5.
const char* kRingProgram =
    "1 BLK FORM CYLINDER Z R20 RI5 L30 DIST+0\n2 TOOL CALL 1 Z\n"
    "3 L X+0 Y+0 Z+10 R0 FMAX\n4 L Z-5 FMAX\n";
const char* kCalibrateInRing =
    "5 TCH PROBE 462 CALIBRATE TS IN RING\n  Q407=+5\n  Q320=+0\n  Q423=+8\n  Q380=+0\n";
const char* kMeasureRing =
    "6 TCH PROBE 421 MEASURE HOLE\n  Q273=+0\n  Q274=+0\n  Q262=10\n  Q325=+0\n"
    "  Q247=+90\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q275=0\n  Q276=0\n"
    "  Q279=0\n  Q280=0\n  Q281=0\n  Q309=0\n  Q330=0\n  Q423=4\n  Q365=1\n";

TEST_F(ProbingTest, Cycle462CalibratesTheBallRadiusInARing) {
    // A ring of radius 5 (the tube's bore), really 0.58 mm off where the probe starts: the
    // coarse pass centres the probe, the fine pass finds ball centres on a circle of 5 - 1.98.
    useMachine(kProbeError);
    ASSERT_EQ(run("1 BLK FORM CYLINDER Z R20 RI5 L30 DIST+0\n2 TOOL CALL 1 Z\n"
                  "3 L X+0 Y+0 Z+10 R0 FMAX\n4 L Z-5 FMAX\n"
                  "5 TCH PROBE 462 CALIBRATE TS IN RING\n  Q407=+5\n  Q320=+0\n  Q423=+8\n"
                  "  Q380=+0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(108), 1.98, 1e-9);
    const Pose end = interpreter->nominalPosition();
    EXPECT_NEAR(end[Axis::X], 0.5, 1e-9);  // over the real ring centre
    EXPECT_NEAR(end[Axis::Y], -0.3, 1e-9);
}

TEST_F(ProbingTest, Cycle463CalibratesTheBallRadiusOnAStud) {
    useMachine(kProbeError);
    ASSERT_EQ(run("1 BLK FORM CYLINDER Z R10 L30 DIST+0\n2 TOOL CALL 1 Z\n"
                  "3 L X+0 Y+0 Z+2 R0 FMAX\n"
                  "4 TCH PROBE 463 CALIBRATE TS ON STUD\n  Q407=+10\n  Q320=+0\n  Q301=+1\n"
                  "  Q423=+8\n  Q380=+0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(108), 1.98, 1e-9);
    auto written = tables::ToolTable::load(dir / "TOOL.T");
    ASSERT_TRUE(written.ok());
    EXPECT_NEAR(written->byNumber(1)->radius, 1.98, 1e-4);
}

// kProbeError's stylus, its ball centre also 0.03 mm off the spindle axis along +X and 0.02
// along -Y (spindle at 0 degrees, CAL_ANG 0 in the default tchprobe.tp).
const std::string kMisalignedProbe = std::string(kProbeError) + "centre_offset = [0.03, -0.02]\n";

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

double centreOffset(const fs::path& file, const char* column) {
    auto table = tables::ProbeTable::load(file);
    EXPECT_TRUE(table.ok());
    if (!table.ok()) return 0.0;
    auto index = table->table().findColumn(column);
    return index ? table->table().number(table->byNumber(1)->row, *index).value_or(0.0) : 0.0;
}

TEST_F(ProbingTest, UncalibratedCentreOffsetMovesTheMeasuredCentre) {
    // The ring (bore radius 5) really at (0.5, -0.3). The control takes the ball centre for the
    // spindle's, which is 0.03 / -0.02 off: every ball centre it computes lies by that much the
    // other way, so 421 finds the centre at (0.47, -0.28). The ball centres lie 5 - 1.98 from
    // the real centre; with the table's r_b 2 the diameter is 2 (3.02 + 2) = 10.04.
    useMachine(kMisalignedProbe);
    ASSERT_EQ(run(std::string(kRingProgram) + kMeasureRing), interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(151), 0.47, 1e-9);
    EXPECT_NEAR(q(152), -0.28, 1e-9);
    EXPECT_NEAR(q(153), 10.04, 1e-9);
}

TEST_F(ProbingTest, Cycle462FindsTheCentreOffsetAndLaterCyclesUseIt) {
    // 462 at CAL_ANG 0 fits the ball centres about C - e (e the offset CAL_OF misses), turned
    // by 180 degrees about C + e: e = (0.03, -0.02) goes to tchprobe.tp, R = 1.98 to TOOL.T.
    // 421 then finds the real ring: centre (0.5, -0.3), diameter 10.
    useMachine(kMisalignedProbe);
    ASSERT_EQ(run(std::string(kRingProgram) + kCalibrateInRing + kMeasureRing),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(108), 1.98, 1e-9);
    EXPECT_NEAR(q(151), 0.5, 1e-9);
    EXPECT_NEAR(q(152), -0.3, 1e-9);
    EXPECT_NEAR(q(153), 10.0, 1e-9);
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF1"), 0.03, 1e-4);
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF2"), -0.02, 1e-4);
    // The reversal turned the spindle by 180 degrees and back to CAL_ANG.
    std::vector<double> orientations;
    for (const canon::Command& c : out.commands) {
        if (const auto* o = std::get_if<canon::SpindleOrient>(&c.body))
            orientations.push_back(o->angleDeg);
    }
    EXPECT_EQ(orientations, (std::vector<double>{180.0, 0.0}));
    // TCHPRAUTO.html in the program's folder logs the calibration with the values before.
    const std::string log = readText(dir / "TCHPRAUTO.html");
    EXPECT_NE(log.find("<h2>Cycle 462 CALIBRATE TS IN RING</h2>"), std::string::npos) << log;
    EXPECT_NE(log.find("<tr><td>R</td><td>2.0000</td><td>1.9800</td></tr>"), std::string::npos);
    EXPECT_NE(log.find("<tr><td>CAL_OF1</td><td>0.0000</td><td>0.0300</td></tr>"),
              std::string::npos);
    EXPECT_NE(log.find("<tr><td>CAL_OF2</td><td>0.0000</td><td>-0.0200</td></tr>"),
              std::string::npos);
    // A second run reads the calibrated offset from the table: 421 alone finds the real ring.
    ASSERT_EQ(run(std::string(kRingProgram) + kMeasureRing), interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(151), 0.5, 1e-9);
    EXPECT_NEAR(q(152), -0.3, 1e-9);
    // Calibrating twice in one run: both go into the log, the second finds what the first set.
    std::string twice = std::string(kRingProgram) + kCalibrateInRing + kCalibrateInRing;
    twice.replace(twice.rfind("5 TCH"), 1, "6");
    ASSERT_EQ(run(twice), interp::RunStatus::Finished) << firstError();
    const std::string both = readText(dir / "TCHPRAUTO.html");
    const size_t second = both.rfind("<h2>Cycle 462");
    ASSERT_NE(second, both.find("<h2>Cycle 462"));
    EXPECT_NE(both.find("<tr><td>CAL_OF1</td><td>0.0300</td><td>0.0300</td></tr>", second),
              std::string::npos)
        << both;
}

TEST_F(ProbingTest, AProbeThatCannotBeTurnedCalibratesItsRadiusWithoutReversal) {
    // TYPE FIXED: the spindle cannot turn the probe, so 462 runs its coarse and fine passes
    // only (spec 6, 462: "None, or in one direction only"). The fine circle's radius does not
    // depend on the stylus's offset: R = 5 - (5 - 1.98) = 1.98; nothing is oriented and
    // CAL_OF is not written.
    useMachine(kMisalignedProbe);
    writeFileAtomically(dir / "tchprobe.tp",
                        "BEGIN TCHPROBE.TP MM\nNO   TYPE   F     DIST  SET_UP\n"
                        "1    FIXED  1000  20    2\n[END]\n");
    ASSERT_EQ(run(std::string(kRingProgram) + kCalibrateInRing), interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(108), 1.98, 1e-9);
    for (const canon::Command& c : out.commands)
        EXPECT_FALSE(std::holds_alternative<canon::SpindleOrient>(c.body));
    const auto table = tables::ProbeTable::load(dir / "tchprobe.tp");
    ASSERT_TRUE(table.ok());
    EXPECT_FALSE(table->table().findColumn("CAL_OF1").has_value());
    // A cable probe (two directions) is reversed as before and finds the offset.
    writeFileAtomically(dir / "tchprobe.tp",
                        "BEGIN TCHPROBE.TP MM\nNO   TYPE   F     DIST  SET_UP\n"
                        "1    TS260  1000  20    2\n[END]\n");
    ASSERT_EQ(run(std::string(kRingProgram) + kCalibrateInRing), interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF1"), 0.03, 1e-4);
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF2"), -0.02, 1e-4);
    // It cannot follow each probing direction: 441's angle tracking stops the next cycle.
    const std::string tracking = std::string(kRingProgram) +
                                 "5 TCH PROBE 441 FAST PROBING\n  Q396=1234\n  Q397=0\n"
                                 "  Q399=1\n  Q400=0\n" +
                                 kMeasureRing;
    ASSERT_EQ(run(tracking), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-024"), std::string::npos) << firstError();
    EXPECT_NE(firstError().find("TS260"), std::string::npos) << firstError();
}

TEST_F(ProbingTest, CentreOffsetAtAnotherCalibrationAngleTurnsWithTheSpindle) {
    // CAL_ANG 90: the probe stands turned by 90 degrees, so the stylus's offset (0.03, -0.02)
    // at spindle angle 0 lies at (0.02, 0.03). 463 on the stud (radius 10, really at
    // (0.5, -0.3)) writes that as CAL_OF1/CAL_OF2.
    useMachine(kMisalignedProbe);
    writeFileAtomically(dir / "tchprobe.tp",
                        "BEGIN TCHPROBE.TP MM\nNO   TYPE   CAL_ANG  F     DIST  SET_UP\n"
                        "1    TS460  +90      1000  20    2\n[END]\n");
    ASSERT_EQ(run("1 BLK FORM CYLINDER Z R10 L30 DIST+0\n2 TOOL CALL 1 Z\n"
                  "3 L X+0 Y+0 Z+2 R0 FMAX\n"
                  "4 TCH PROBE 463 CALIBRATE TS ON STUD\n  Q407=+10\n  Q320=+0\n  Q301=+1\n"
                  "  Q423=+8\n  Q380=+0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(108), 1.98, 1e-9);
    // The old table had no CAL_OF columns: they are added.
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF1"), 0.02, 1e-4);
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF2"), 0.03, 1e-4);
}

// The old single-touch cycles on the plate 100 x 60 x 40 placed with the fixture's setup error:
// its left face is the line through (1.5, -0.8) turned by 0.7 degrees, outward normal
// n = (-cos a, -sin a). A ball of radius 2 at height y = 30 moving along +X touches it where
// n . (c - (1.5, -0.8)) = 2.
const char* kPlate =
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n3 TOOL CALL 1 Z\n";

double leftFaceTouchX(double y) {
    const double a = 0.7 * std::numbers::pi / 180.0;
    return 1.5 - (2.0 + (y + 0.8) * std::sin(a)) / std::cos(a);
}

TEST_F(ProbingTest, Cycle0ProbesOneAxisIntoItsResultParameter) {
    ASSERT_EQ(run(std::string(kPlate) + "4 L X-5 Y+30 Z+20 R0 FMAX\n"
                                        "5 TCH PROBE 0.0 REF. PLANE Q5 X+\n"
                                        "6 TCH PROBE 0.1 X-5 Y+30 Z-5\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double x = leftFaceTouchX(30.0);
    EXPECT_NEAR(q(5), x + 2.0, 1e-9);  // the surface: the ball centre + r_b along +X
    // The trigger position without stylus length and radius: the gauge point (L 0).
    EXPECT_NEAR(q(115), x, 1e-9);
    EXPECT_NEAR(q(116), 30.0, 1e-9);
    EXPECT_NEAR(q(117), -7.0, 1e-9);
    EXPECT_EQ(q(118), 0.0);
    // Back at the start of the touch: the pre-position, the tool tip r_b below the ball centre.
    const Pose end = interpreter->nominalPosition();
    EXPECT_NEAR(end[Axis::X], -5.0, 1e-9);
    EXPECT_NEAR(end[Axis::Z], -7.0, 1e-9);
    // The Portuguese keywords and a missing probing axis.
    ASSERT_EQ(run(std::string(kPlate) + "4 TCH PROBE 0.0 PLANO DE REFERENCIA Q7 X+\n"
                                        "5 TCH PROBE 0.1 X-5 Y+30 Z-5\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(7), x + 2.0, 1e-9);
    ASSERT_EQ(run(std::string(kPlate) + "4 TCH PROBE 0.0 REF. PLANE Q5\n"
                                        "5 TCH PROBE 0.1 X-5 Y+30 Z-5\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("probing axis"), std::string::npos) << firstError();
}

TEST_F(ProbingTest, Cycle1ProbesAlongAPolarAngle) {
    // From s = (-5, 30) along d = (cos 30, sin 30): n . (s + t d - p0) = 2.
    ASSERT_EQ(run(std::string(kPlate) + "4 TCH PROBE 1.0 POLAR DATUM PLANE\n"
                                        "5 TCH PROBE 1.1 X ANGLE: +30\n"
                                        "6 TCH PROBE 1.2 X-5 Y+30 Z-5\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double b = 30.0 * std::numbers::pi / 180.0;
    const double t = (6.5 * std::cos(a) - 30.8 * std::sin(a) - 2.0) / std::cos(b - a);
    EXPECT_NEAR(q(115), -5.0 + t * std::cos(b), 1e-9);
    EXPECT_NEAR(q(116), 30.0 + t * std::sin(b), 1e-9);
    EXPECT_NEAR(q(117), -7.0, 1e-9);
}

TEST_F(ProbingTest, Cycle3MeasuresFromWhereTheProbeStands) {
    const std::string measure =
        "5 TCH PROBE 3.0 MEASURING\n6 TCH PROBE 3.1 Q1\n"
        "7 TCH PROBE 3.2 X ANGLE: +0\n";
    // The ball at (-5, 30, -5) probes along +X at F100 within 10, then retracts MB 1.
    ASSERT_EQ(run(std::string(kPlate) + "4 L X-5 Y+30 Z-7 R0 FMAX\n" + measure +
                  "8 TCH PROBE 3.3 DIST +10 F100 MB1 REFERENCE SYSTEM: 0\n9 Q10 = Q4\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double x = leftFaceTouchX(30.0);
    EXPECT_NEAR(q(1), x, 1e-9);
    EXPECT_NEAR(q(2), 30.0, 1e-9);
    EXPECT_NEAR(q(3), -5.0, 1e-9);
    EXPECT_EQ(q(10), 0.0);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], x - 1.0, 1e-9);
    bool probingFeed = false;
    for (const canon::Command& c : out.commands) {
        if (const auto* move = std::get_if<canon::LinearMove>(&c.body)) {
            probingFeed = probingFeed || move->feed == 100.0;
        }
    }
    EXPECT_TRUE(probingFeed);
    // Nothing within 3 mm: no error, Q4 = -1, the probe 1 back from where the path ended.
    ASSERT_EQ(run(std::string(kPlate) + "4 L X-5 Y+30 Z-7 R0 FMAX\n" + measure +
                  "8 TCH PROBE 3.3 DIST +3 F100 MB1 REFERENCE SYSTEM: 0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(q(4), -1.0);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], -3.0, 1e-9);
    // Deflected at the start (the ball inside the plate): ERRORMODE 1 gives Q4 = -1, without
    // 3.4 (ERRORMODE 0) it is PRB-002.
    const std::string inside = std::string(kPlate) + "4 L X+50 Y+30 Z-7 R0 FMAX\n" + measure +
                               "8 TCH PROBE 3.3 DIST +10 F100 MB1 REFERENCE SYSTEM: 0\n";
    ASSERT_EQ(run(inside + "9 TCH PROBE 3.4 ERRORMODE1\n"), interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(q(4), -1.0);
    ASSERT_EQ(run(inside + "9 Q10 = 1\n"), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-002"), std::string::npos) << firstError();
    EXPECT_EQ(q(10), 0.0);  // the cycle stopped the program before block 9
}

TEST_F(ProbingTest, Cycle4ProbesAlongAVector) {
    // From the ball at (50, 30, 12) along (1, 0, -1)/sqrt 2 onto the real top at -0.2: the ball
    // centre stops at z 1.8, x 60.2; MB 2 takes it back 2 along the vector.
    const std::string program = std::string(kPlate) +
                                "4 L X+50 Y+30 Z+10 R0 FMAX\n"
                                "5 TCH PROBE 4.0 MEASURING IN 3-D\n6 TCH PROBE 4.1 Q1\n"
                                "7 TCH PROBE 4.2 IX+1 IY+0 IZ-1\n"
                                "8 TCH PROBE 4.3 ABST+45 F100 MB2 REFERENCE SYSTEM:";
    ASSERT_EQ(run(program + "0\n"), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(q(1), 60.2, 1e-9);
    EXPECT_NEAR(q(2), 30.0, 1e-9);
    EXPECT_NEAR(q(3), 1.8, 1e-9);
    EXPECT_EQ(q(4), 0.0);
    const Pose end = interpreter->nominalPosition();
    EXPECT_NEAR(end[Axis::X], 60.2 - std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(end[Axis::Z], 1.8 + std::sqrt(2.0) - 2.0, 1e-9);
    // REFERENCE SYSTEM 1: machine coordinates (the start preset lies at machine Z -400).
    ASSERT_EQ(run(program + "1\n"), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(q(1), 60.2, 1e-9);
    EXPECT_NEAR(q(3), -398.2, 1e-9);
}

TEST_F(ProbingTest, Cycles013ReportWithoutTheCentreOffsetAnd4WithIt) {
    // The stylus's ball lies 0.03 / -0.02 off the spindle axis and tchprobe.tp holds exactly
    // that (calibrated): the control's ball centre is the real one. Cycles 0, 1 and 3 report
    // positions without CAL_OF (the spindle axis), 4 with it (spec 1.5, 4, 5).
    useMachine(
        "base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n"
        "[[simulation.tool_error]]\ntool = 1\ncentre_offset = [0.03, -0.02]\n");
    writeFileAtomically(dir / "tchprobe.tp",
                        "BEGIN TCHPROBE.TP MM\nNO   TYPE   CAL_OF1  CAL_OF2  F     DIST  SET_UP\n"
                        "1    TS460  +0.03    -0.02    1000  20    2\n[END]\n");
    // 0: the control's ball centre pre-positioned at (-5, 30, -5) touches the left face where
    // leftFaceTouchX(30) says; the spindle axis lies 0.03 / -0.02 away from it.
    ASSERT_EQ(run(std::string(kPlate) + "4 L X-5 Y+30 Z+20 R0 FMAX\n"
                                        "5 TCH PROBE 0.0 REF. PLANE Q5 X+\n"
                                        "6 TCH PROBE 0.1 X-5 Y+30 Z-5\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double x = leftFaceTouchX(30.0);
    EXPECT_NEAR(q(5), x - 0.03 + 2.0, 1e-9);
    EXPECT_NEAR(q(115), x - 0.03, 1e-9);
    EXPECT_NEAR(q(116), 30.0 + 0.02, 1e-9);
    EXPECT_NEAR(q(117), -7.0, 1e-9);
    // 1: the same pre-position, along 0 degrees from X: the same touch, Q115-Q117 alike.
    ASSERT_EQ(run(std::string(kPlate) + "4 TCH PROBE 1.0 POLAR DATUM PLANE\n"
                                        "5 TCH PROBE 1.1 X ANGLE: +0\n"
                                        "6 TCH PROBE 1.2 X-5 Y+30 Z-5\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(115), x - 0.03, 1e-9);
    EXPECT_NEAR(q(116), 30.02, 1e-9);
    // 3: the spindle at (-5, 30) puts the ball at y 29.98; it touches there, and reports the
    // spindle axis: x - 0.03 and y 30.
    ASSERT_EQ(run(std::string(kPlate) + "4 L X-5 Y+30 Z-7 R0 FMAX\n"
                                        "5 TCH PROBE 3.0 MEASURING\n6 TCH PROBE 3.1 Q1\n"
                                        "7 TCH PROBE 3.2 X ANGLE: +0\n"
                                        "8 TCH PROBE 3.3 DIST +10 F100 MB1 REFERENCE SYSTEM: 0\n"
                                        "9 Q10 = Q4\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(1), leftFaceTouchX(29.98) - 0.03, 1e-9);
    EXPECT_NEAR(q(2), 30.0, 1e-9);
    EXPECT_NEAR(q(3), -5.0, 1e-9);
    EXPECT_EQ(q(10), 0.0);
    // 4: the ball at (50.03, 29.98, 12) along (1, 0, -1) onto the top at -0.2 stops 10.2
    // further along X, and 4 reports the corrected ball centre.
    ASSERT_EQ(run(std::string(kPlate) + "4 L X+50 Y+30 Z+10 R0 FMAX\n"
                                        "5 TCH PROBE 4.0 MEASURING IN 3-D\n6 TCH PROBE 4.1 Q1\n"
                                        "7 TCH PROBE 4.2 IX+1 IY+0 IZ-1\n"
                                        "8 TCH PROBE 4.3 ABST+45 F100 MB2 REFERENCE SYSTEM:0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(1), 60.23, 1e-9);
    EXPECT_NEAR(q(2), 29.98, 1e-9);
    EXPECT_NEAR(q(3), 1.8, 1e-9);
}

TEST_F(ProbingTest, Cycle460CalibratesRadiusAndLengthOnASphere) {
    // The sphere (radius 12.5, centre programmed at (0, 0, -20)) lies shifted by the setup error
    // (0.5, -0.3, 0); the probe (table L 0, R 2) is really 0.1 longer with a ball of 1.98.
    // The ball-centre sphere has radius 14.48: R = 14.48 - 12.5. Its south pole rests on the
    // north pole at -7.5 when the gauge point stands 0.1 above it: L = 0.1 with Q434 = -20.
    // The program has no BLK FORM: the simulated blank lies elsewhere on the table.
    useMachine(std::string(kProbeError) +
               "[simulation.calibration_sphere]\ncentre = [0.0, 0.0, -20.0]\nradius = 12.5\n"
               "[simulation.blank]\nmin = [100.0, 100.0, -40.0]\nmax = [200.0, 160.0, 0.0]\n");
    const std::string program =
        "1 TOOL CALL 1 Z\n2 L X+0 Y+0 Z+10 R0 FMAX\n"
        "3 TCH PROBE 460 CALIBRATE TS ON SPHERE\n  Q407=12.5\n  Q320=0\n"
        "  Q301=1\n  Q423=4\n  Q380=+0\n  Q433=1\n  Q434=-20\n  Q455=";
    ASSERT_EQ(run(program + "0\n"), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(q(108), 1.98, 1e-6);
    EXPECT_NEAR(q(114), 0.1, 1e-6);
    auto written = tables::ToolTable::load(dir / "TOOL.T");
    ASSERT_TRUE(written.ok());
    EXPECT_NEAR(written->byNumber(1)->radius, 1.98, 1e-4);
    EXPECT_NEAR(written->byNumber(1)->length, 0.1, 1e-4);
    // It ends at the start height over the real centre.
    const Pose end = interpreter->nominalPosition();
    EXPECT_NEAR(end[Axis::X], 0.5, 1e-6);
    EXPECT_NEAR(end[Axis::Y], -0.3, 1e-6);
    EXPECT_NEAR(end[Axis::Z], 10.0, 1e-6);
    // The stylus runs true: the reversal finds no centre offset.
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF1"), 0.0, 1e-9);
    // The 3D calibration (option 92) is not available.
    fs::remove(dir / "TOOL.T");
    fs::remove(dir / "tchprobe.tp");
    // With the stylus 0.03 / -0.02 off the spindle, the reversal at the equator finds it; the
    // probe ends with the (uncalibrated) control's ball centre over the sphere's, the spindle
    // by that offset beside it.
    useMachine(kMisalignedProbe +
               "[simulation.calibration_sphere]\ncentre = [0.0, 0.0, -20.0]\nradius = 12.5\n"
               "[simulation.blank]\nmin = [100.0, 100.0, -40.0]\nmax = [200.0, 160.0, 0.0]\n");
    ASSERT_EQ(run(program + "0\n"), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(q(108), 1.98, 1e-6);
    EXPECT_NEAR(q(114), 0.1, 1e-6);
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF1"), 0.03, 1e-4);
    EXPECT_NEAR(centreOffset(dir / "tchprobe.tp", "CAL_OF2"), -0.02, 1e-4);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 0.47, 1e-6);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], -0.28, 1e-6);
    ASSERT_EQ(run(program + "15\n"), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("Q455"), std::string::npos) << firstError();
}

}  // namespace
}  // namespace kerf::klartext

namespace kerf::klartext {
namespace {

// A set-up program that only probes (no BLK FORM) touches the machine's simulated blank: the
// built-in default, 100 x 60 x 40 with its top at Z 0 and its corner at the origin.
TEST_F(ProbingTest, WithoutBlkFormTheDefaultSimulatedBlankIsProbed) {
    ASSERT_EQ(run("1 TOOL CALL 1 Z\n2 L X-5 Y+30 Z+20 R0 FMAX\n"
                  "3 TCH PROBE 0.0 REF. PLANE Q5 X+\n4 TCH PROBE 0.1 X-5 Y+30 Z-5\n"
                  "5 TCH PROBE 0.0 REF. PLANE Q6 Z-\n6 TCH PROBE 0.1 X+50 Y+30 Z+10\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(5), leftFaceTouchX(30.0) + 2.0, 1e-9);
    EXPECT_NEAR(q(6), -0.2, 1e-9);  // the top, 0.2 lower than programmed
}

// [simulation.blank] places the blank in the frame of the machine file's preset, turned about
// that preset: a program whose preset lies elsewhere (X +10, Z -5 in the machine) finds it
// there.
TEST_F(ProbingTest, TheSimulatedBlankStaysAtTheMachineFilesPreset) {
    useMachine(
        "base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n"
        "[simulation.blank]\nmin = [-50.0, -50.0, -20.0]\nmax = [50.0, 50.0, 0.0]\n");
    presetInMachine = Pose{{10.0, 0.0, -405.0}};
    ASSERT_EQ(run("1 TOOL CALL 1 Z\n2 L X-70 Y+0 Z+20 R0 FMAX\n"
                  "3 TCH PROBE 0.0 REF. PLANE Q5 X+\n4 TCH PROBE 0.1 X-70 Y+0 Z-5\n"
                  "5 TCH PROBE 0.0 REF. PLANE Q6 Z-\n6 TCH PROBE 0.1 X+0 Y+0 Z+15\n"),
              interp::RunStatus::Finished)
        << firstError();
    // The left face x = -50 turned by a about the file's preset, then shifted: where it crosses
    // y = 0 (the program's y = 0 is the file preset's), the ball touches r_b / cos a before it.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double t = (0.8 + 50.0 * std::sin(a)) / std::cos(a);
    const double faceX = -50.0 * std::cos(a) - t * std::sin(a) + 1.5;
    EXPECT_NEAR(q(5), faceX - 2.0 / std::cos(a) + 2.0 - 10.0, 1e-9);
    EXPECT_NEAR(q(6), -0.2 + 5.0, 1e-9);  // the real top, 5 above this program's zero
    // A blank whose sides are not ordered is refused with its keys.
    DiagnosticList problems;
    EXPECT_FALSE(
        machine::parseMachine("base = \"mill\"\n[simulation.blank]\nmin = [0.0, 0.0, 0.0]\n"
                              "max = [10.0, 10.0, -5.0]\n",
                              "bad.toml", &problems));
    ASSERT_FALSE(problems.empty());
    EXPECT_NE(problems.front().format().find("simulation.blank.min.z"), std::string::npos)
        << problems.front().format();
}

// Cycle 400 with Q305 = 0 makes the basic rotation the active preset's: row 0's SPC, next to the
// datum 419/417 write there. The next program starts from that preset with its basic rotation
// (as the panel and kerf run --preset 0 start it): the part lies square, so a touch along the
// turned Y onto the front face finds it at Y 0 at both ends, where the unturned axes would see
// it 80 tan 0.7deg apart.
TEST_F(ProbingTest, TheNextProgramRunsInThePresetsBasicRotation) {
    const char* setup =
        "1 TOOL CALL 1 Z\n2 L X-20 Y-20 Z+50 R0 FMAX\n"
        "3 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+80\n  Q266=+0\n"
        "  Q272=2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q307=0\n  Q305=0\n"
        "4 TCH PROBE 419 DATUM IN ONE AXIS\n  Q263=+0\n  Q264=+30\n  Q261=-5\n  Q320=0\n"
        "  Q260=+20\n  Q272=1\n  Q267=+1\n  Q305=0\n  Q333=+0\n  Q303=+1\n"
        "5 TCH PROBE 419 DATUM IN ONE AXIS\n  Q263=+50\n  Q264=+0\n  Q261=-5\n  Q320=0\n"
        "  Q260=+20\n  Q272=2\n  Q267=+1\n  Q305=0\n  Q333=+0\n  Q303=+1\n"
        "6 TCH PROBE 417 DATUM IN TS AXIS\n  Q263=+50\n  Q264=+30\n  Q294=+0\n  Q320=0\n"
        "  Q260=+20\n  Q305=0\n  Q333=+0\n  Q303=+1\n";
    ASSERT_EQ(run(setup), interp::RunStatus::Finished) << firstError();
    auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets.ok());
    const tables::PresetData* row0 = presets->byNumber(0);
    ASSERT_NE(row0, nullptr);
    EXPECT_NEAR(presets->basicRotationDeg(0), 0.7, 1e-9);
    // The real corner and top in machine coordinates.
    EXPECT_NEAR(*row0->axis('X'), 1.5, 1e-4);
    EXPECT_NEAR(*row0->axis('Y'), -0.8, 1e-4);
    EXPECT_NEAR(*row0->axis('Z'), -400.2, 1e-4);

    presetInMachine = Pose{{*row0->axis('X'), *row0->axis('Y'), *row0->axis('Z')}};
    basicRotationDeg = presets->basicRotationDeg(0);
    ASSERT_EQ(run("1 TOOL CALL 1 Z\n2 L X+10 Y-10 Z+20 R0 FMAX\n"
                  "3 TCH PROBE 0.0 REF. PLANE Q5 Y+\n4 TCH PROBE 0.1 X+10 Y-10 Z-5\n"
                  "5 TCH PROBE 0.0 REF. PLANE Q6 Y+\n6 TCH PROBE 0.1 X+80 Y-10 Z-5\n"
                  "7 L X+100 Y+0 Z+10 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(5), 0.0, 1e-4);
    EXPECT_NEAR(q(6), 0.0, 1e-4);
    // X100 Y0 is the far end of the front edge: the real corner plus 100 along the turned edge,
    // in the stream's (unturned) frame of this preset.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const Pose end = interpreter->nominalPosition();
    EXPECT_NEAR(end[Axis::X], 100.0 * std::cos(a), 1e-9);
    EXPECT_NEAR(end[Axis::Y], 100.0 * std::sin(a), 1e-9);
    EXPECT_NEAR(end[Axis::Z], 10.0, 1e-9);
}

// Cycle 10 turns on top of the preset's basic rotation; ROT 0 leaves the basic rotation.
TEST_F(ProbingTest, Cycle10RotatesOnTopOfTheBasicRotation) {
    basicRotationDeg = 30.0;
    const double a = 30.0 * std::numbers::pi / 180.0;
    const double b = 40.0 * std::numbers::pi / 180.0;
    ASSERT_EQ(run("1 L X+10 Y+0 Z+10 R0 FMAX\n"), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 10.0 * std::cos(a), 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], 10.0 * std::sin(a), 1e-9);
    ASSERT_EQ(run("1 CYCL DEF 10.0 ROTATION\n2 CYCL DEF 10.1 ROT+10\n3 L X+10 Y+0 Z+10 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 10.0 * std::cos(b), 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], 10.0 * std::sin(b), 1e-9);
    ASSERT_EQ(run("1 CYCL DEF 10.0 ROTATION\n2 CYCL DEF 10.1 ROT+10\n"
                  "3 CYCL DEF 10.0 ROTATION\n4 CYCL DEF 10.1 ROT+0\n5 L X+10 Y+0 Z+10 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 10.0 * std::cos(a), 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], 10.0 * std::sin(a), 1e-9);
}

// Cycle 247 activates a preset row with its basic rotation.
TEST_F(ProbingTest, Cycle247BringsThePresetsBasicRotation) {
    writeFileAtomically(dir / "PRESET.PR",
                        "BEGIN PRESET.PR MM\nNR   DOC  X         Y         Z         SPC\n"
                        "0         +0        +0        -400      +0\n"
                        "3         +20       +0        -400      -90\n[END]\n");
    ASSERT_EQ(run("1 CYCL DEF 247 DATUM SETTING\n  Q339=3\n2 L X+10 Y+0 Z+10 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    // Row 3: origin at machine X 20, turned by -90 degrees: X10 lies 10 towards -Y.
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], 20.0, 1e-9);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], -10.0, 1e-9);
}

}  // namespace
}  // namespace kerf::klartext
