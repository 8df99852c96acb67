// The TT cycles with touches from the machine's latch (settings.touchesFromMachine,
// docs/probing.md "Tool measurement with the TT"): each touch of the tool on the stylus leaves
// the interpreter as a probe move carrying the real tool on the TT, and the cycle computes with
// the gauge point the machine latched. The TT as in tool_measurement_test.cpp: a disc of diameter
// 40, top at machine (-200, 50, -300); the start preset at machine Z -400.
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "core/tables/tool_table.h"
#include "tests/core/interp/klartext/latching_machine.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

// Tool 3: L 100, R 5, 4 teeth; really 0.05 longer and 0.012 thinner (as tool 5 of
// examples/probing/machine.toml). Tool 9: a calibration pin L 50, R 5; really 0.1 longer and
// 0.02 thinner.
constexpr const char* kTools =
    "BEGIN TOOL.T MM\nT    NAME   L      R      DL     DR     CUT  TL\n"
    "3    D10    +100   +5     +0     +0     4\n"
    "9    PIN    +50    +5     +0     +0     0\n[END]\n";

// A rotating D10 (R-OFFS empty: offset R, CUT 4): n = 100 m/min / (5 mm x 0.0063), probing at
// the measuring tolerance 0.005 mm per revolution.
constexpr double kRotatingFeed = 0.005 * 100.0 / (5.0 * 0.0063);
constexpr double kStationaryFeed = 50.0;  // probing_feed of [simulation.tool_probe]

class ToolMeasurementLatchTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_tt_latch_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs the program: with `machine`, its touches come from that machine's latch. Nothing the
    // cycle writes appears while a touch is still out at the machine.
    interp::RunStatus run(const std::string& body, LatchingMachine* latching) {
        KlartextSettings settings;
        settings.machine = &machineConfig;
        settings.tools = &tools;
        settings.ncRoot = dir;
        settings.presetInMachine = Pose{{0.0, 0.0, -400.0}};
        settings.touchesFromMachine = latching != nullptr;
        interpreter = std::make_unique<KlartextInterpreter>(sources, settings);
        writeFileAtomically(dir / "P.H", "0 BEGIN PGM P MM\n" + body + "99 END PGM P MM\n");
        if (!interpreter->load(dir / "P.H")) return interp::RunStatus::Failed;
        LatchingMachine plain([](const canon::ProbeSurface&, const Vec3&) { return false; }, 0.05,
                              0.0);
        std::vector<std::string> absent;
        for (const char* file : {"TOOL.T", "SIMTOOLS.TXT", "TTCALIB.TXT"})
            if (!fs::exists(dir / file)) absent.push_back(file);
        return runLatched(*interpreter, latching != nullptr ? *latching : plain, [&] {
            for (const std::string& file : absent)
                EXPECT_FALSE(fs::exists(dir / file)) << file << " before the last touch";
        });
    }
    // A fresh NC root: the next run starts from the machine file's TT and the table's tools.
    void forget() {
        for (const char* file : {"TOOL.T", "SIMTOOLS.TXT", "TTCALIB.TXT"})
            fs::remove(dir / file);
    }
    double q(uint16_t index) const { return interpreter->parameters().get(QRef{QKind::Q, index}); }
    std::string firstError() const {
        for (const Diagnostic& d : interpreter->diagnostics())
            if (d.severity == Severity::Error) return d.code + ": " + d.format();
        return {};
    }
    const tables::ToolData writtenRow(int tool) const {
        auto table = tables::ToolTable::load(dir / "TOOL.T");
        EXPECT_TRUE(table.ok());
        if (!table.ok() || table->byNumber(tool) == nullptr) return {};
        return *table->byNumber(tool);
    }
    std::map<std::string, double> calibration() const {
        std::map<std::string, double> values;
        std::ifstream in(dir / "TTCALIB.TXT");
        std::string key;
        double value = 0.0;
        while (in >> key >> value)
            values[key] = value;
        return values;
    }
    template <typename T>
    static size_t count(const LatchingMachine& machine) {
        size_t n = 0;
        for (const canon::Command& c : machine.commands)
            n += std::holds_alternative<T>(c.body);
        return n;
    }

    fs::path dir;
    machine::MachineConfig machineConfig = *machine::parseMachine(
        "base = \"mill\"\n[simulation.tool_probe]\nenabled = true\n"
        "centre = [-200.0, 50.0, -300.0]\ndiameter = 40.0\n"
        "[[simulation.tool_error]]\ntool = 3\nlength = 0.05\nradius = -0.012\n"
        "[[simulation.tool_error]]\ntool = 9\nlength = 0.1\nradius = -0.02\n",
        "test.toml");
    tables::ToolTable tools = *tables::ToolTable::parse(kTools);
    program::SourceRegistry sources;
    std::unique_ptr<KlartextInterpreter> interpreter;
};

bool onTheStylus(const canon::ProbeSurface& surface, const Vec3& tip) {
    return surface.touches(tip);
}

const std::string kMeasure483 =
    "1 TOOL CALL 3 Z S1000\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
    "3 TCH PROBE 483 MEASURE TOOL\n  Q340=1\n  Q260=+200\n  Q341=0\n";

TEST_F(ToolMeasurementLatchTest, LatchedTouchesMeasureTheRealToolAsThePlainRunDoes) {
    LatchingMachine machine(onTheStylus, 0.05, kRotatingFeed);
    ASSERT_EQ(run(kMeasure483, &machine), interp::RunStatus::Finished) << firstError();
    // Both touches went to the machine (the radius, then the length), and none was a feed move
    // of the interpreter's own.
    EXPECT_EQ(machine.probeMoves, 2);
    EXPECT_EQ(machine.probingFeedMoves, 0);
    // By hand: the real tool is 0.05 longer and 0.012 thinner than L 100, R 5.
    EXPECT_NEAR(q(115), 0.05, 1e-6);
    EXPECT_NEAR(q(116), -0.012, 1e-6);
    EXPECT_EQ(q(199), 0.0);
    const tables::ToolData row = writtenRow(3);
    EXPECT_NEAR(row.deltaLength, 0.05, 1e-6);
    EXPECT_NEAR(row.deltaRadius, -0.012, 1e-6);
    // The table was written once, by the pass that completed: one tool update in the stream.
    EXPECT_EQ(count<canon::ToolUpdate>(machine), 1u);
    // The length touch latched with the end face on the top (workpiece Z +100): the tip the
    // control computes with L = 100 stood at 100.05, R (= R-OFFS) right of the centre.
    const auto probe = interpreter->programStatus().probe;
    ASSERT_TRUE(probe && probe->triggered);
    EXPECT_NEAR(probe->position[Axis::Z], 100.05, 1e-6);
    EXPECT_NEAR(probe->position[Axis::X], -195.0, 1e-9);

    const double latched[] = {q(115), q(116), row.deltaLength, row.deltaRadius};
    forget();
    ASSERT_EQ(run(kMeasure483, nullptr), interp::RunStatus::Finished) << firstError();
    const tables::ToolData plainRow = writtenRow(3);
    const double plain[] = {q(115), q(116), plainRow.deltaLength, plainRow.deltaRadius};
    for (size_t i = 0; i < std::size(plain); ++i)
        EXPECT_NEAR(latched[i], plain[i], 1e-6) << i;
}

TEST_F(ToolMeasurementLatchTest, TheMeasuredLengthIsWhereTheDrivesTouched) {
    // The drives see the stylus 0.1 higher than the interpreter's model of it: the end face
    // meets it 0.1 earlier, and the measured length is 0.1 longer. 481 compares only.
    LatchingMachine machine(
        [](const canon::ProbeSurface& surface, const Vec3& tip) {
            return surface.touches(tip - Vec3(0.0, 0.0, 0.1));
        },
        0.05, kRotatingFeed);
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 481 TOOL LENGTH\n  Q340=2\n  Q260=+200\n  Q341=0\n",
                  &machine),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(machine.probeMoves, 1);
    EXPECT_NEAR(q(115), 0.05 + 0.1, 1e-6);
    EXPECT_FALSE(fs::exists(dir / "TOOL.T"));
}

TEST_F(ToolMeasurementLatchTest, RadiusFromTheLatchedSideTouch) {
    LatchingMachine machine(onTheStylus, 0.05, kRotatingFeed);
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 482 TOOL RADIUS\n  Q340=1\n  Q260=+200\n  Q341=0\n",
                  &machine),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(machine.probeMoves, 1);
    EXPECT_NEAR(q(116), -0.012, 1e-6);
    EXPECT_NEAR(writtenRow(3).deltaRadius, -0.012, 1e-6);
    // The tool axis stopped 20 + 4.988 left of the stylus's centre, the end face 2 below its top.
    const auto probe = interpreter->programStatus().probe;
    ASSERT_TRUE(probe && probe->triggered);
    EXPECT_NEAR(probe->position[Axis::X], -200.0 - 20.0 - 4.988, 1e-6);
    EXPECT_NEAR(probe->position[Axis::Z], 98.0, 1e-9);
}

TEST_F(ToolMeasurementLatchTest, EachToothIsLatchedAtItsOwnOrientation) {
    // Old format with Q341 = 1: the rotating touch, then the 4 teeth with the spindle stopped,
    // each oriented once (no pass repeats an orientation at the machine).
    LatchingMachine machine(onTheStylus, 0.05, 0.0);
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 31.0 TOOL LENGTH\n4 TCH PROBE 31.1 CHECK: 1 Q5\n"
                  "5 TCH PROBE 31.2 HEIGHT: +120\n6 TCH PROBE 31.3 PROBING THE TEETH: 1\n",
                  &machine),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(machine.probeMoves, 5);
    EXPECT_EQ(count<canon::SpindleOrient>(machine), 4u);
    EXPECT_NEAR(q(115), 0.05, 1e-6);
    EXPECT_EQ(q(5), 0.0);
    // Started for the rotating touch and stopped for the teeth, each once; the program's spindle
    // stood still, so the cycle has nothing to put back.
    EXPECT_EQ(count<canon::SpindleControl>(machine), 2u);
}

TEST_F(ToolMeasurementLatchTest, CalibrationFromLatchedTouchesSurvivesTheRun) {
    // The pin, really 0.1 longer and 0.02 thinner, touches the top 0.1 early (TOP_Z -299.9) and
    // each side 0.02 early (diameter 40 - 2 x 0.02); the centre stays. Standing still: probing
    // feed 50.
    LatchingMachine calibrating(onTheStylus, 0.05, kStationaryFeed);
    ASSERT_EQ(run("1 TOOL CALL 9 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 480 CALIBRATE TT\n  Q260=+200\n",
                  &calibrating),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(calibrating.probeMoves, 5);  // the top and four sides
    std::map<std::string, double> latched = calibration();
    EXPECT_NEAR(latched["TOP_X"], -200.0, 1e-6);
    EXPECT_NEAR(latched["TOP_Y"], 50.0, 1e-6);
    EXPECT_NEAR(latched["TOP_Z"], -299.9, 1e-6);
    EXPECT_NEAR(latched["DIAMETER"], 39.96, 1e-6);
    // The next run measures tool 3 against the calibrated TT: L 100.05 - 0.1, R 4.988 + 0.02.
    LatchingMachine measuring(onTheStylus, 0.05, kRotatingFeed);
    ASSERT_EQ(run(kMeasure483, &measuring), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(q(115), -0.05, 1e-6);
    EXPECT_NEAR(q(116), 0.008, 1e-6);

    forget();
    ASSERT_EQ(run("1 TOOL CALL 9 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 480 CALIBRATE TT\n  Q260=+200\n",
                  nullptr),
              interp::RunStatus::Finished)
        << firstError();
    for (const auto& [key, value] : calibration())
        EXPECT_NEAR(latched[key], value, 1e-6) << key;
}

TEST_F(ToolMeasurementLatchTest, AProbeMoveWithoutATouchIsTheManualsError) {
    // The drives' probe input never triggers: PRB-001 as in a plain run that misses, and the
    // table stays as it was.
    LatchingMachine machine([](const canon::ProbeSurface&, const Vec3&) { return false; }, 0.05,
                            kRotatingFeed);
    ASSERT_EQ(run(kMeasure483, &machine), interp::RunStatus::Failed);
    EXPECT_EQ(machine.probeMoves, 1);
    EXPECT_NE(firstError().find("PRB-001"), std::string::npos) << firstError();
    EXPECT_FALSE(fs::exists(dir / "TOOL.T"));
}

}  // namespace
}  // namespace kerf::klartext
