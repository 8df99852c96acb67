// The TT cycles 30-33 / 480-483 through the Klartext interpreter, on a simulated TT: a disc of
// diameter 40 whose top is at machine (-200, 50, -300); the start preset lies at machine Z -400,
// so the top is at workpiece Z +100. The real tools differ from the table by the machine file's
// [[simulation.tool_error]].
#include <filesystem>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class Recorder : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
};

// Tool 1: a workpiece touch probe, ball radius 2. Tool 3: L 100, R 5, 4 teeth, LTOL 0.1, RTOL 0.05,
// LBREAK 0.3, RBREAK 0.2. Tool 9: a calibration pin L 50, R 5.
tables::ToolTable toolTable() {
    auto table = *tables::ToolTable::parse(tables::ToolTable::createDefault());
    for (int number : {1, 3, 9})
        EXPECT_FALSE(table.addTool(number));
    EXPECT_FALSE(table.setNumber(1, "L", 50.0));  // the workpiece probe of the Q330 tests
    EXPECT_FALSE(table.setNumber(1, "R", 2.0));
    EXPECT_FALSE(table.setNumber(3, "L", 100.0));
    EXPECT_FALSE(table.setNumber(3, "R", 5.0));
    EXPECT_FALSE(table.setNumber(3, "CUT", 4));
    EXPECT_FALSE(table.setNumber(3, "LTOL", 0.1));
    EXPECT_FALSE(table.setNumber(3, "RTOL", 0.05));
    EXPECT_FALSE(table.setNumber(3, "LBREAK", 0.3));
    EXPECT_FALSE(table.setNumber(3, "RBREAK", 0.2));
    EXPECT_FALSE(table.setNumber(9, "L", 50.0));
    EXPECT_FALSE(table.setNumber(9, "R", 5.0));
    return table;
}

class ToolMeasurementTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_tt_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        tools = toolTable();
    }
    void TearDown() override { fs::remove_all(dir); }

    void useMachine(const std::string& errors) {
        machine = *machine::parseMachine(
            "base = \"mill\"\n[simulation.tool_probe]\nenabled = true\n"
            "centre = [-200.0, 50.0, -300.0]\ndiameter = 40.0\n" +
                errors,
            "test.toml");
    }

    interp::RunStatus run(const std::string& body) {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.tools = &tools;
        settings.ncRoot = dir;
        settings.presetInMachine[Axis::Z] = -400.0;
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
    tables::ToolTable written() const {
        auto table = tables::ToolTable::load(dir / "TOOL.T");
        EXPECT_TRUE(table.ok());
        return *table;
    }
    template <typename T>
    std::vector<T> commandsOf() const {
        std::vector<T> found;
        for (const canon::Command& c : out.commands)
            if (const auto* body = std::get_if<T>(&c.body)) found.push_back(*body);
        return found;
    }

    fs::path dir;
    machine::MachineConfig machine;
    tables::ToolTable tools = *tables::ToolTable::parse("BEGIN TOOL.T MM\nT\n[END]\n");
    program::SourceRegistry sources;
    Recorder out;
    std::unique_ptr<KlartextInterpreter> interpreter;
};

const char* kLength481 =
    "1 TOOL CALL 3 Z S1000\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
    "3 TCH PROBE 481 TOOL LENGTH\n  Q340=1 ;CHECK\n  Q260=+200 ;CLEARANCE HEIGHT\n"
    "  Q341=0 ;PROBING THE TEETH\n";

TEST_F(ToolMeasurementTest, LengthCheckWritesTheDeviationIntoDL) {
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = 0.05\n");
    ASSERT_EQ(run(std::string(kLength481) + "4 L Z+100 R0 FMAX\n"), interp::RunStatus::Finished)
        << firstError();
    // The real tool is 0.05 longer than L: DL = +0.05, within LTOL (status 0).
    EXPECT_NEAR(q(115), 0.05, 1e-9);
    EXPECT_EQ(q(199), 0.0);
    const tables::ToolData* row = written().byNumber(3);
    ASSERT_NE(row, nullptr);
    EXPECT_NEAR(row->deltaLength, 0.05, 1e-9);
    EXPECT_NEAR(row->length, 100.0, 1e-9);
    EXPECT_FALSE(row->locked);
    // Positioned with L = 100, the end face met the top (workpiece Z +100) when the programmed
    // tip was 0.05 above it.
    const auto probe = interpreter->programStatus().probe;
    ASSERT_TRUE(probe && probe->triggered);
    EXPECT_NEAR(probe->position[Axis::Z], 100.05, 1e-9);
    EXPECT_NEAR(probe->position[Axis::X], -200.0 + 5.0, 1e-9);  // R-OFFS empty: offset R
    EXPECT_NEAR(probe->position[Axis::Y], 50.0, 1e-9);
    // The new DL takes effect at once: Q114 and the tool geometry of the stream.
    EXPECT_NEAR(q(114), 100.05, 1e-9);
    const auto updates = commandsOf<canon::ToolUpdate>();
    ASSERT_FALSE(updates.empty());
    EXPECT_NEAR(updates.back().geometry.lengthMm, 100.05, 1e-9);
    // The tool rotated for the length measurement (R-OFFS = R): n = 100 m/min / (5 mm x
    // 0.0063) = 3174.6 rpm, clockwise (DIRECT -1 cuts with M3); the program's spindle state
    // (stopped) comes back afterwards.
    const auto spindles = commandsOf<canon::SpindleControl>();
    ASSERT_GE(spindles.size(), 2u);
    EXPECT_EQ(spindles.front().direction, canon::SpindleDirection::Clockwise);
    EXPECT_NEAR(spindles.front().speedRpm, 100.0 / (5.0 * 0.0063), 1e-9);
    EXPECT_EQ(spindles.back().direction, canon::SpindleDirection::Stopped);
    // The probing feed: measuring tolerance 0.005 mm x rpm.
    bool probingFeed = false;
    for (const auto& move : commandsOf<canon::LinearMove>())
        probingFeed = probingFeed || std::abs(move.feed - 0.005 * 100.0 / (5.0 * 0.0063)) < 1e-9;
    EXPECT_TRUE(probingFeed);
}

TEST_F(ToolMeasurementTest, StationaryToolStopsTheRunningSpindleAndRestartsItAfterwards) {
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = 0.05\n");
    ASSERT_FALSE(tools.setNumber(3, "R-OFFS", 0.0));  // over the centre, spindle stopped
    ASSERT_EQ(run("1 TOOL CALL 3 Z S1000\n2 L X+0 Y+0 Z+250 R0 FMAX M3\n"
                  "3 TCH PROBE 481 TOOL LENGTH\n  Q340=1\n  Q260=+200\n  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(115), 0.05, 1e-9);
    const auto spindles = commandsOf<canon::SpindleControl>();
    // M3, stop for the touch, M3 again, and the stop of END PGM.
    ASSERT_EQ(spindles.size(), 4u);
    EXPECT_EQ(spindles[1].direction, canon::SpindleDirection::Stopped);
    EXPECT_EQ(spindles[2].direction, canon::SpindleDirection::Clockwise);
    EXPECT_EQ(spindles[2].speedRpm, 1000.0);
    const auto probe = interpreter->programStatus().probe;
    ASSERT_TRUE(probe && probe->triggered);
    EXPECT_NEAR(probe->position[Axis::X], -200.0, 1e-9);
    // The probing feed of a stationary spindle.
    bool probingFeed = false;
    for (const auto& move : commandsOf<canon::LinearMove>())
        probingFeed = probingFeed || move.feed == 50.0;
    EXPECT_TRUE(probingFeed);
}

TEST_F(ToolMeasurementTest, RadiusCheckWritesTheDeviationIntoDR) {
    useMachine("[[simulation.tool_error]]\ntool = 3\nradius = -0.012\n");
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 482 TOOL RADIUS\n  Q340=1\n  Q260=+200\n  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(116), -0.012, 1e-9);
    EXPECT_EQ(q(199), 0.0);
    const tables::ToolData* row = written().byNumber(3);
    EXPECT_NEAR(row->deltaRadius, -0.012, 1e-9);
    EXPECT_NEAR(row->deltaLength, 0.0, 1e-12);
    // The side touch: the tool axis stopped 20 + 4.988 left of the centre, its end face 2
    // (offset_tool_axis) below the top.
    const auto probe = interpreter->programStatus().probe;
    ASSERT_TRUE(probe && probe->triggered);
    EXPECT_NEAR(probe->position[Axis::X], -200.0 - 20.0 - 4.988, 1e-9);
    EXPECT_NEAR(probe->position[Axis::Z], 98.0, 1e-9);
}

TEST_F(ToolMeasurementTest, FirstMeasurementWritesLAndRAndClearsTheDeltas) {
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = -0.2\nradius = 0.03\n");
    ASSERT_FALSE(tools.setNumber(3, "DL", 0.5));
    ASSERT_FALSE(tools.setNumber(3, "DR", -0.1));
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 483 MEASURE TOOL\n  Q340=0\n  Q260=+200\n  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    // The real tool: L + DL - 0.2 = 100.3, R + DR + 0.03 = 4.93.
    const tables::ToolData* row = written().byNumber(3);
    EXPECT_NEAR(row->length, 100.3, 1e-9);
    EXPECT_NEAR(row->radius, 4.93, 1e-9);
    EXPECT_EQ(row->deltaLength, 0.0);
    EXPECT_EQ(row->deltaRadius, 0.0);
    EXPECT_EQ(q(115), 0.0);  // mode 0 gives no deviation
    EXPECT_EQ(q(116), 0.0);
}

TEST_F(ToolMeasurementTest, WearAndBreakageLockTheTool) {
    // 0.2 longer: beyond LTOL 0.1, within LBREAK 0.3: worn.
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = 0.2\n");
    ASSERT_EQ(run(std::string(kLength481) + "4 TOOL CALL 3 Z\n"), interp::RunStatus::Failed);
    EXPECT_EQ(q(199), 1.0);
    EXPECT_TRUE(written().byNumber(3)->locked);
    EXPECT_NEAR(written().byNumber(3)->deltaLength, 0.2, 1e-9);
    // The locked tool cannot be called again in the same program.
    EXPECT_NE(firstError().find("tool 3 is locked"), std::string::npos) << firstError();

    // Radius 0.25 smaller: beyond RBREAK 0.2: broken.
    fs::remove(dir / "TOOL.T");
    useMachine("[[simulation.tool_error]]\ntool = 3\nradius = -0.25\n");
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 TCH PROBE 483 MEASURE TOOL\n  Q340=1\n  Q260=+200\n"
                  "  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(q(199), 2.0);
    EXPECT_NEAR(q(116), -0.25, 1e-9);
    EXPECT_NEAR(q(115), 0.0, 1e-9);
    EXPECT_TRUE(written().byNumber(3)->locked);
}

TEST_F(ToolMeasurementTest, CompareOnlyLeavesTheTableAlone) {
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = 0.2\n");
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 TCH PROBE 481 TOOL LENGTH\n  Q340=2\n  Q260=+200\n"
                  "  Q341=0\n3 TOOL CALL 3 Z\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(115), 0.2, 1e-9);
    EXPECT_EQ(q(199), 1.0);  // the status, but no lock
    EXPECT_FALSE(fs::exists(dir / "TOOL.T"));
}

TEST_F(ToolMeasurementTest, OldFormatWithIndividualTeethAndAStatusParameter) {
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = 0.05\n");
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n3 Q199 = 7\n"
                  "4 TCH PROBE 31.0 TOOL LENGTH\n5 TCH PROBE 31.1 CHECK: 1 Q5\n"
                  "6 TCH PROBE 31.2 HEIGHT: +120\n7 TCH PROBE 31.3 PROBING THE TEETH: 1\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(115), 0.05, 1e-9);
    EXPECT_EQ(q(5), 0.0);
    EXPECT_EQ(q(199), 7.0);  // 31 leaves Q199 alone
    EXPECT_NEAR(written().byNumber(3)->deltaLength, 0.05, 1e-9);
    // Each of the 4 teeth at its own spindle orientation.
    const auto orientations = commandsOf<canon::SpindleOrient>();
    ASSERT_EQ(orientations.size(), 4u);
    EXPECT_EQ(orientations[1].angleDeg, 90.0);
    EXPECT_EQ(orientations[3].angleDeg, 270.0);
}

TEST_F(ToolMeasurementTest, CalibrationCorrectsTheProbeForLaterMeasurements) {
    // The calibration pin (tool 9) is really 0.1 longer and 0.02 thinner than its table entry,
    // so calibration puts the top 0.1 higher (Z -299.9) and the disc 0.04 narrower (39.96).
    // Tool 3, really 0.05 longer and 0.012 thinner, then measures L 100.05 - 0.1 and
    // R 4.988 + 0.02.
    useMachine(
        "[[simulation.tool_error]]\ntool = 9\nlength = 0.1\nradius = -0.02\n"
        "[[simulation.tool_error]]\ntool = 3\nlength = 0.05\nradius = -0.012\n");
    ASSERT_EQ(run("1 TOOL CALL 9 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 480 CALIBRATE TT\n  Q260=+200\n"
                  "4 TOOL CALL 3 Z\n5 TCH PROBE 483 MEASURE TOOL\n  Q340=1\n  Q260=+200\n"
                  "  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(115), -0.05, 1e-9);
    EXPECT_NEAR(q(116), 0.008, 1e-9);
}

TEST_F(ToolMeasurementTest, WirelessCalibration484FromWhereThePinStands) {
    // The same pin and tool as above: 484 calibrates from the pin's height (Z+250 here) and
    // stops first with Q536 = 0, so the operator can position the pin.
    useMachine(
        "[[simulation.tool_error]]\ntool = 9\nlength = 0.1\nradius = -0.02\n"
        "[[simulation.tool_error]]\ntool = 3\nlength = 0.05\nradius = -0.012\n");
    ASSERT_EQ(run("1 TOOL CALL 9 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 484 CALIBRATE IR TT\n  Q536=+0\n"
                  "4 TOOL CALL 3 Z\n5 TCH PROBE 483 MEASURE TOOL\n  Q340=1\n  Q260=+200\n"
                  "  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(115), -0.05, 1e-9);
    EXPECT_NEAR(q(116), 0.008, 1e-9);
    auto programStops = [this] {
        size_t n = 0;
        for (const auto& stop : commandsOf<canon::ProgramStop>())
            n += stop.kind == canon::StopKind::Program;
        return n;
    };
    EXPECT_EQ(programStops(), 1u);
    ASSERT_EQ(run("1 TOOL CALL 9 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 484 CALIBRATE IR TT\n  Q536=+1\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(programStops(), 1u);  // the recorder keeps the first run's: no new stop
}

TEST_F(ToolMeasurementTest, CalibrationSurvivesTheRun) {
    // The calibration of one run (as in CalibrationCorrectsTheProbeForLaterMeasurements) is kept
    // in TTCALIB.TXT of the NC root: a later run measures tool 3 against the calibrated TT.
    useMachine(
        "[[simulation.tool_error]]\ntool = 9\nlength = 0.1\nradius = -0.02\n"
        "[[simulation.tool_error]]\ntool = 3\nlength = 0.05\nradius = -0.012\n");
    ASSERT_EQ(run("1 TOOL CALL 9 Z\n2 L X+0 Y+0 Z+250 R0 FMAX\n"
                  "3 TCH PROBE 480 CALIBRATE TT\n  Q260=+200\n"),
              interp::RunStatus::Finished)
        << firstError();
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 TCH PROBE 483 MEASURE TOOL\n  Q340=2\n  Q260=+200\n"
                  "  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(115), -0.05, 1e-9);
    EXPECT_NEAR(q(116), 0.008, 1e-9);
}

TEST_F(ToolMeasurementTest, TheRealToolStaysTheSameFromRunToRun) {
    // Tool 3 is really 100.05 long and 4.988 in radius (L 100, R 5 in its row). Each run starts
    // from the table the run before wrote, as `kerf run` and the panel do.
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = 0.05\nradius = -0.012\n");
    const std::string check =
        "1 TOOL CALL 3 Z\n2 TCH PROBE 483 MEASURE TOOL\n  Q340=1\n"
        "  Q260=+200\n  Q341=0\n";
    for (int pass = 0; pass < 2; ++pass) {
        ASSERT_EQ(run(check), interp::RunStatus::Finished) << firstError();
        tools = written();
        // The same deviations from L and R each time, not the error added to the corrected row.
        EXPECT_NEAR(q(115), 0.05, 1e-9) << "pass " << pass;
        EXPECT_NEAR(q(116), -0.012, 1e-9) << "pass " << pass;
        EXPECT_NEAR(tools.byNumber(3)->deltaLength, 0.05, 1e-9);
        EXPECT_FALSE(tools.byNumber(3)->locked);
    }
    // Measured anew (Q340=0: L and R written, DL = DR = 0), the next check finds nothing to
    // correct.
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 TCH PROBE 483 MEASURE TOOL\n  Q340=0\n  Q260=+200\n"
                  "  Q341=0\n"),
              interp::RunStatus::Finished)
        << firstError();
    tools = written();
    EXPECT_NEAR(tools.byNumber(3)->length, 100.05, 1e-9);
    EXPECT_NEAR(tools.byNumber(3)->radius, 4.988, 1e-9);
    ASSERT_EQ(run(check), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(q(115), 0.0, 1e-9);
    EXPECT_NEAR(q(116), 0.0, 1e-9);
}

TEST_F(ToolMeasurementTest, OldCalibrationCycle30) {
    useMachine("");
    ASSERT_EQ(run("1 TOOL CALL 9 Z\n2 TCH PROBE 30.0 CALIBRATE TT\n3 TCH PROBE 30.1 HEIGHT: +90\n"
                  "4 L Z+250 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    // The last move of the cycle: over the calibrated centre, which is the real one.
    bool overCentre = false;
    for (const auto& move : commandsOf<canon::RapidMove>()) {
        overCentre = overCentre || (std::abs(move.target[Axis::X] + 200.0) < 1e-9 &&
                                    std::abs(move.target[Axis::Y] - 50.0) < 1e-9);
    }
    EXPECT_TRUE(overCentre);
}

// Cycle 427 on the blank's top (Z 0) or left face (X 0), monitoring tool 3 (RBREAK 0.2).
std::string coordinate427(int axis, int direction, double max, double min) {
    return "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
           "3 TOOL CALL 1 Z\n4 L X-10 Y+30 Z+50 R0 FMAX\n"
           "5 TCH PROBE 427 MEASURE COORDINATE\n  Q263=+" +
           std::string(axis == 3 ? "50" : "0") +
           "\n  Q264=+30\n  Q261=" + std::string(axis == 3 ? "+0" : "-5") +
           "\n  Q320=0\n  Q272=" + std::to_string(axis) + "\n  Q267=" + std::to_string(direction) +
           "\n  Q260=+20\n  Q281=0\n  Q288=" + std::to_string(max) +
           "\n  Q289=" + std::to_string(min) + "\n  Q309=0\n  Q330=3\n";
}

TEST_F(ToolMeasurementTest, ToolMonitoringQ330CorrectsTheMachiningTool) {
    useMachine("");
    // The top lies at 0, the limits' middle at 0.15: the tool cut 0.15 too deep, DL += 0.15.
    ASSERT_FALSE(tools.setNumber(3, "DL", 0.01));
    ASSERT_EQ(run(coordinate427(3, -1, 0.2, 0.1)), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(written().byNumber(3)->deltaLength, 0.16, 1e-9);
    EXPECT_EQ(written().byNumber(3)->deltaRadius, 0.0);
    // The left face, touched along +X, lies at 0 where -0.1 was meant: 0.1 more material is gone,
    // DR += 0.1. The probe (tool 1) keeps its data.
    fs::remove(dir / "TOOL.T");
    ASSERT_EQ(run(coordinate427(1, 1, 0.1, -0.3)), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(written().byNumber(3)->deltaRadius, 0.1, 1e-9);
    EXPECT_EQ(written().byNumber(1)->deltaRadius, 0.0);
    EXPECT_NEAR(q(108), 2.0, 1e-12);
    // 0.5 beyond the middle: more than RBREAK 0.2, the tool is locked and the program stops.
    fs::remove(dir / "TOOL.T");
    ASSERT_EQ(run(coordinate427(3, -1, 0.6, 0.4)), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-007"), std::string::npos) << firstError();
    EXPECT_TRUE(written().byNumber(3)->locked);
    // A tool to monitor that is not in the table.
    std::string program = coordinate427(3, -1, 0.2, 0.1);
    program.replace(program.find("Q330=3"), 6, "Q330=7");
    ASSERT_EQ(run(program), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("Q330 = 7"), std::string::npos) << firstError();
}

TEST_F(ToolMeasurementTest, ToolMonitoringQ330NamesAnIndexedToolOrAToolByName) {
    // Tool 3 and its index 3.2 (named FINISH) are different rows: Q330 = 3.2 corrects the
    // index's DL by the 0.15 the top lies below the limits' middle, tool 3 keeps its data;
    // Q330 = "FINISH" finds the same row by its name and corrects its DR on the left face.
    useMachine("");
    auto row = [](std::vector<std::string> cells) {
        std::string line;
        for (const std::string& cell : cells)
            line += cell + std::string(10 - cell.size(), ' ');
        return line + "\n";
    };
    tools = *tables::ToolTable::parse(
        "BEGIN TOOL.T MM\n" + row({"T", "NAME", "L", "R", "DL", "DR", "TL", "RBREAK"}) +
        row({"1", "TS", "+50", "+2", "+0", "+0", "", "+0"}) +
        row({"3", "ROUGH", "+100", "+5", "+0", "+0", "", "+0.2"}) +
        row({"3.2", "FINISH", "+100", "+5", "+0", "+0", "", "+0.2"}) + "[END]\n");
    std::string program = coordinate427(3, -1, 0.2, 0.1);
    program.replace(program.find("Q330=3"), 6, "Q330=3.2");
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(written().byNumber(3, 2)->deltaLength, 0.15, 1e-9);
    EXPECT_EQ(written().byNumber(3)->deltaLength, 0.0);
    fs::remove(dir / "TOOL.T");
    program = coordinate427(1, 1, 0.1, -0.3);
    program.replace(program.find("Q330=3"), 6, "Q330=\"FINISH\"");
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << firstError();
    EXPECT_NEAR(written().byNumber(3, 2)->deltaRadius, 0.1, 1e-9);
    EXPECT_EQ(written().byNumber(3)->deltaRadius, 0.0);
    // A name that is not in the table is reported with it.
    program.replace(program.find("FINISH"), 6, "NOSUCH");
    ASSERT_EQ(run(program), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("Q330 = NOSUCH"), std::string::npos) << firstError();
}

TEST_F(ToolMeasurementTest, Errors) {
    // No TT on the machine.
    machine = *machine::parseMachine("base = \"mill\"\n", "test.toml");
    ASSERT_EQ(run(kLength481), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-023"), std::string::npos) << firstError();
    useMachine("");
    // No tool called.
    ASSERT_EQ(run("1 TCH PROBE 481 TOOL LENGTH\n  Q340=1\n  Q260=+200\n  Q341=0\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-012"), std::string::npos) << firstError();
    // Q340 out of range: found by the check at its line and column.
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 TCH PROBE 481 TOOL LENGTH\n  Q340=3\n  Q260=+200\n"
                  "  Q341=0\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("P.H:4:3:"), std::string::npos) << firstError();
    // A sub-block without its header, and one without a number.
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 TCH PROBE 31.1 CHECK: 1\n"), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("without TCH PROBE 31.0"), std::string::npos) << firstError();
    ASSERT_EQ(run("1 TOOL CALL 3 Z\n2 TCH PROBE 32.0 TOOL RADIUS\n3 TCH PROBE 32.1 CHECK: X\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("a number after ':'"), std::string::npos) << firstError();
    // A tool so much shorter than its table entry that it never reaches the stylus
    // (safety distance 5, measuring path 10).
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = -6\n");
    ASSERT_EQ(run(kLength481), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-001"), std::string::npos) << firstError();
    // ... and one so much longer that it is already on the stylus at the start of the touch.
    useMachine("[[simulation.tool_error]]\ntool = 3\nlength = 6\n");
    ASSERT_EQ(run(kLength481), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("PRB-002"), std::string::npos) << firstError();
}

}  // namespace
}  // namespace kerf::klartext
