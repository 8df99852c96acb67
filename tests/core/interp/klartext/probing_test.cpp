// TCH PROBE cycles through the Klartext interpreter: the simulated part is the program's blank
// placed with the machine file's setup error (shift 1.5 / -0.8 / -0.2 mm, 0.7 degrees).
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "core/tables/preset_table.h"

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

    interp::RunStatus run(const std::string& body) {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.tools = &tools;
        settings.ncRoot = dir;
        settings.presetInMachine[Axis::Z] = -400.0;  // the start preset, machine coordinates
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
    // A touch that finds nothing: no blank at all.
    EXPECT_EQ(run("1 TOOL CALL 1 Z\n2 L Z+50 R0 FMAX\n"
                  "3 TCH PROBE 417 DATUM IN TS AXIS\n  Q263=+0\n  Q264=+0\n  Q294=+0\n"
                  "  Q320=0\n  Q260=+20\n  Q305=0\n  Q333=+0\n  Q303=+1\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-001"), std::string::npos) << firstError();
    // A probing cycle Kerf does not have yet is refused before the program starts.
    EXPECT_EQ(run("1 TCH PROBE 444 PROBING IN 3-D\n  Q263=+0\n"), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("not supported"), std::string::npos) << firstError();
    // Out-of-range values are found by the check, at their line.
    EXPECT_EQ(run("1 TOOL CALL 1 Z\n2 TCH PROBE 419 DATUM IN ONE AXIS\n  Q272=7\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("P.H:3:"), std::string::npos) << firstError();
}

}  // namespace
}  // namespace kerf::klartext
