// G75/G76 probing moves (spec part 2 §3) and the machine's workpiece origin, with the machine's
// answers written by hand: where the probe latched, where the axes stopped, or that nothing
// touched. Positions in the stream are radii (X) in mm.
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/canon/trace_format.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::fagor {
namespace {

namespace fs = std::filesystem;

Pose xz(double x, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Z] = z;
    return p;
}

class Recorder final : public canon::Sink {
public:
    void consume(const canon::Command& c) override {
        std::string line;
        canon::TraceFormat format;
        format.axes = axisBit(Axis::X) | axisBit(Axis::Z);
        canon::appendCommand(line, c, format);
        lines.push_back(line);
    }
    std::vector<std::string> lines;
};

// The machine's answer at a sync point.
using Machine = std::function<interp::WorldSnapshot(const FagorInterpreter&, int syncIndex)>;

// Nothing moves: the probe touches (or leaves) at the programmed end point.
interp::WorldSnapshot idealMachine(const FagorInterpreter& interpreter, int) {
    interp::WorldSnapshot world;
    world.position = interpreter.nominalPosition();
    world.probeTriggered = true;
    world.probePosition = world.position;
    return world;
}

class FagorProbing : public testing::Test {
protected:
    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        root = fs::temp_directory_path() /
               ("kerf_fagor_probe_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(root);
        fs::create_directories(root);
        auto loaded = machine::loadMachine("lathe");
        ASSERT_TRUE(static_cast<bool>(loaded));
        lathe = std::move(*loaded);
        settings.machine = &lathe;
        settings.ncRoot = root;
        settings.zeroOffsetFile = root / "fagor_zero_offsets.tab";
    }
    void TearDown() override { fs::remove_all(root); }

    interp::RunStatus run(const std::string& text, const Machine& machine = idealMachine) {
        std::ofstream(root / "program.pim", std::ios::binary) << text;
        interpreter = std::make_unique<FagorInterpreter>(sources, settings);
        if (!interpreter->load(root / "program.pim")) return interp::RunStatus::Failed;
        interp::RunStatus status = interp::RunStatus::BudgetUsed;
        int syncs = 0;
        for (int slice = 0; slice < 10000; ++slice) {
            status = interpreter->run(out, 1);
            if (status == interp::RunStatus::NeedsSync) {
                interpreter->resume(machine(*interpreter, syncs++));
            } else if (status != interp::RunStatus::BudgetUsed) {
                break;
            }
        }
        return status;
    }

    std::string diagnostics() const {
        std::string text;
        for (const Diagnostic& d : interpreter->diagnostics())
            text += d.format() + "\n";
        return text;
    }

    double parameter(int number) const {
        double value = 0.0;
        Problem problem;
        EXPECT_TRUE(interpreter->parameters().get(number, value, problem));
        return value;
    }

    fs::path root;
    machine::MachineConfig lathe;
    FagorSettings settings;
    program::SourceRegistry sources;
    std::unique_ptr<FagorInterpreter> interpreter;
    Recorder out;
};

TEST_F(FagorProbing, ContinuesFromWhereTheAxesStopped) {
    // The probe latches at Z 3.2 on the way from Z10 to Z-5 and the axes stop 0.2 mm further,
    // at Z3: the CNC takes that actual position as the theoretical one (spec part 2 §3, 1.), so
    // X50 (G01, radius 25) runs from there and APOSZ reads 3.
    const auto status =
        run("N10 G90 G151 G0 X40 Z10\n"
            "N20 G75 Z-5 F100\n"
            "N30 X50\n"
            "(P100 = APOSZ)\n"
            "M30\n",
            [](const FagorInterpreter& i, int sync) {
                interp::WorldSnapshot world;
                world.position = i.nominalPosition();
                if (sync == 0) {
                    world.position = xz(20.0, 3.0);
                    world.probeTriggered = true;
                    world.probePosition = xz(20.0, 3.2);
                }
                return world;
            });
    ASSERT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    const std::vector<std::string> expected = {
        "1:1 N10 RAPID X20.0000 Z10.0000",
        "2:1 N20 PROBE X20.0000 Z-5.0000 F100.000",
        "2:1 N20 SYNC PROBE",
        "3:1 N30 LINE X25.0000 Z3.0000 F100.000",
        "4:1 SYNC POSITION",
        "5:1 END M30",
    };
    EXPECT_EQ(out.lines, expected);
    EXPECT_DOUBLE_EQ(parameter(100), 3.0);
}

TEST_F(FagorProbing, ReachingTheEndPointWithoutTouchingIsAnErrorAtTheBlock) {
    auto missed = [](const FagorInterpreter& i, int) {
        interp::WorldSnapshot world;
        world.position = i.nominalPosition();
        return world;
    };
    EXPECT_EQ(run("G90 G0 X40 Z10\nN20 G1 G75 Z-5 F100\nX50\nM30\n", missed),
              interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() +
                                 ":2:8: error: G75 reached its end point without the probe "
                                 "touching\n");
    // Nothing after the probing block is emitted.
    ASSERT_FALSE(out.lines.empty());
    EXPECT_EQ(out.lines.back(), "2:1 N20 SYNC PROBE");
}

TEST_F(FagorProbing, G76EndsWhenTheProbeLeavesAndReportsAProbeStillTouching) {
    auto missed = [](const FagorInterpreter& i, int) {
        interp::WorldSnapshot world;
        world.position = i.nominalPosition();
        return world;
    };
    EXPECT_EQ(run("G90 G0 X40 Z10\nG76 X60 F50\nM30\n", missed), interp::RunStatus::Failed);
    ASSERT_GE(out.lines.size(), 2u);
    EXPECT_EQ(out.lines[1], "2:1 PROBE X30.0000 Z10.0000 F50.000 UNTIL-RELEASE");
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() +
                                 ":2:1: error: G76 reached its end point with the probe still "
                                 "touching\n");
}

TEST_F(FagorProbing, PrbmodOneAndProberrOffAcceptAMiss) {
    auto missed = [](const FagorInterpreter& i, int) {
        interp::WorldSnapshot world;
        world.position = i.nominalPosition();
        return world;
    };
    // PRBMOD = 1: no error (spec part 2 §5.16).
    EXPECT_EQ(run("(PRBMOD = 1)\nG90 G0 X40 Z10\nG75 Z-5 F100\nZ20\nM30\n", missed),
              interp::RunStatus::Finished)
        << diagnostics();
    EXPECT_EQ(out.lines.back(), "5:1 END M30");
    // PROBERR off: no error either.
    settings.probeError = false;
    out.lines.clear();
    EXPECT_EQ(run("G90 G0 X40 Z10\nG75 Z-5 F100\nM30\n", missed), interp::RunStatus::Finished)
        << diagnostics();
}

TEST_F(FagorProbing, NeedsAProgrammedFeed) {
    // Without F a G01 runs at the machine's maximum feed; a probe move refuses that.
    EXPECT_EQ(run("G90 G0 X40 Z10\nG75 Z-5\nM30\n"), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() +
                                 ":2:1: error: G75 needs a programmed feed F greater than 0\n");
    EXPECT_EQ(run("G90 G0 X40 Z10 F0\nG76 Z-5\nM30\n"), interp::RunStatus::Failed);
}

TEST_F(FagorProbing, IsAStraightMoveInWorkpieceCoordinates) {
    const std::string error =
        ": error: G75 is a straight probing move in workpiece coordinates: not with G06, G08, "
        "G09, G36-G39 or G53\n";
    EXPECT_EQ(run("G90 G0 X40 Z10\nG53 G75 Z10 F100\nM30\n"), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() + ":2:5" + error);
    EXPECT_EQ(run("G90 G0 X40 Z10\nG39 R2 G75 Z10 F100\nM30\n"), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() + ":2:8" + error);
}

TEST_F(FagorProbing, CancelsNoseCompensationAndIsNotModal) {
    // After G75 the CNC is in G01 and G40 (spec part 2 §3, 5.): Z0 is a G01 whose tip goes to
    // the programmed point; under G42 with the 1 mm nose radius it would be offset.
    settings.toolOffsetFile = root / "fagor_tool_offsets.tab";
    std::ofstream(settings.toolOffsetFile) << "D1 X0 Z0 F3 R1\n";
    const auto status =
        run("G90 G152 G0 X20 Z10 T1 D1\n"
            "G1 G42 X20 Z5 F100\n"
            "G75 X10\n"
            "Z0\n"
            "M30\n");
    ASSERT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    ASSERT_GE(out.lines.size(), 5u);
    EXPECT_EQ(out.lines[out.lines.size() - 2], "4:1 LINE X10.0000 Z0.0000 F100.000");
}

TEST_F(FagorProbing, AnRptRangeMayEndWithTheProbingBlock) {
    // N20 runs once in sequence, then twice more through RPT: three probe moves.
    const auto status =
        run("N10 G90 G152 G0 X20 Z10\n"
            "N20 G75 Z-5 F100\n"
            "N30 (RPT N20, N20) N2\n"
            "M30\n");
    ASSERT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    int probes = 0;
    for (const std::string& line : out.lines)
        probes += line.find("PROBE X") != std::string::npos ? 1 : 0;
    EXPECT_EQ(probes, 3);
}

TEST_F(FagorProbing, ConflictsWithTheMotionFunctionsTheSpecNames) {
    for (const char* block :
         {"G00 G75 Z5", "G02 G75 Z5", "G03 G75 Z5", "G33 G75 Z5 L2", "G34 G75 Z5 L2 K0",
          "G41 G75 Z5", "G42 G75 Z5", "G52 G75 Z5", "G75 G76 Z5"}) {
        out.lines.clear();
        EXPECT_EQ(run(std::string(block) + "\nM30\n"), interp::RunStatus::Failed) << block;
        EXPECT_NE(diagnostics().find("(error 7)"), std::string::npos) << block << diagnostics();
    }
}

TEST_F(FagorProbing, TheMachinesWorkpieceOriginIsThePresetWithoutAZeroOffset) {
    // The machine file puts the workpiece origin at machine Z 300 (radius X 0): machine
    // coordinates are the stream's plus 300 in Z. POSZ (machine) at Z10 reads 310, APOSZ 10,
    // and G53 Z350 goes to stream Z 50.
    settings.presetInMachine = xz(0.0, 300.0);
    const auto status =
        run("G90 G152 G0 X20 Z10\n"
            "(P100 = POSZ, P101 = APOSZ)\n"
            "G53 G0 Z350\n"
            "M30\n");
    ASSERT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    EXPECT_DOUBLE_EQ(interpreter->streamOrigin()[Axis::Z], 300.0);
    EXPECT_DOUBLE_EQ(parameter(100), 310.0);
    EXPECT_DOUBLE_EQ(parameter(101), 10.0);
    ASSERT_GE(out.lines.size(), 3u);
    EXPECT_EQ(out.lines[out.lines.size() - 2], "3:1 RAPID X20.0000 Z50.0000");
}

TEST_F(FagorProbing, AZeroOffsetSelectedInTheTableWinsOverTheMachinesPreset) {
    std::ofstream(root / "fagor_zero_offsets.tab") << "G54 X0 Z120\nACTIVE G54\n";
    settings.presetInMachine = xz(0.0, 300.0);
    ASSERT_EQ(run("G90 G0 X20 Z10\nM30\n"), interp::RunStatus::Finished) << diagnostics();
    EXPECT_DOUBLE_EQ(interpreter->streamOrigin()[Axis::Z], 120.0);
}

}  // namespace
}  // namespace kerf::fagor
