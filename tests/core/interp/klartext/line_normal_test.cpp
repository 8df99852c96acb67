// LN, the straight line with 3D tool compensation (docs/klartext.md, "LN"): the tip of a cutter
// that differs from the CAM system's by DR and DR2 moves so that it touches the surface where the
// CAM system's did (the geometry by hand in cutter_oversize_test.cpp), M107/M108 permit and
// forbid positive oversizes, TCPM turns the tool to TX TY TZ or to the normal.
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "core/tables/tool_table.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

// Tools of the CAM system's sizes and the oversizes of the actual ones (mm):
// 1 ball R5 DR/DR2 -0.1 (and -0.1 more in the TOOL CALLs below), 2 end mill R5 DR -0.5,
// 3 toroid R5 R2 2 DR -0.3 DR2 -0.1, 4 ball R5 DR/DR2 +0.2, 5 ball R5 DR -0.5 (R2 beyond R),
// 6 end mill R5 DR2 -0.1 (R2 below 0), 7 ball R5 without oversize.
constexpr const char* kTools =
    "BEGIN TOOL.T MM\n"
    "T     NAME     L        R        R2       DL       DR       DR2\n"
    "1     BALL     +0       +5       +5       +0       -0.1     -0.1\n"
    "2     END      +0       +5       +0       +0       -0.5     +0\n"
    "3     TORUS    +0       +5       +2       +0       -0.3     -0.1\n"
    "4     BIG      +0       +5       +5       +0       +0.2     +0.2\n"
    "5     WORN     +0       +5       +5       +0       -0.5     +0\n"
    "6     FLAT     +0       +5       +0       +0       +0       -0.1\n"
    "7     EXACT    +0       +5       +5       +0       +0       +0\n"
    "[END]\n";

class LineNormalTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_ln_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        tools.emplace(*tables::ToolTable::parse(kTools));
    }
    void TearDown() override { fs::remove_all(dir); }

    interp::RunStatus run(const std::string& machineName, const std::string& blocks) {
        machine = *machine::loadMachine(machineName);
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        settings.tools = &*tools;
        for (const machine::AxisConfig& axis : machine.axes)
            settings.presetInMachine[*axisFromLetter(axis.letter)] = axis.presetPosition;
        k = std::make_unique<KlartextInterpreter>(sources, settings);
        sink.moves.clear();
        const fs::path path = dir / "P.H";
        writeFileAtomically(path, "0 BEGIN PGM P MM\n" + blocks + "99 END PGM P MM\n");
        if (!k->load(path)) return interp::RunStatus::Failed;
        interp::RunStatus status;
        do {
            status = k->run(sink, 1000);
        } while (status == interp::RunStatus::BudgetUsed);
        return status;
    }
    // The tip where the run ended, in workpiece coordinates.
    void expectAt(double x, double y, double z) const {
        const Pose p = k->nominalPosition();
        EXPECT_NEAR(p[Axis::X], x, 1e-9);
        EXPECT_NEAR(p[Axis::Y], y, 1e-9);
        EXPECT_NEAR(p[Axis::Z], z, 1e-9);
    }
    std::string firstError() const {
        for (const Diagnostic& d : k->diagnostics()) {
            if (d.severity == Severity::Error) return d.message();
        }
        return "";
    }
    struct Recorder : canon::Sink {
        void consume(const canon::Command& c) override {
            if (const auto* m = std::get_if<canon::LinearMove>(&c.body))
                moves.push_back({c.location.blockNumber, m->target});
        }
        std::vector<std::pair<int64_t, Pose>> moves;
    } sink;
    Pose lastMoveOf(int64_t block) const {
        Pose last;
        for (const auto& [at, target] : sink.moves)
            if (at == block) last = target;
        return last;
    }

    fs::path dir;
    machine::MachineConfig machine;
    std::optional<tables::ToolTable> tools;  // no default constructor
    program::SourceRegistry sources;
    std::unique_ptr<KlartextInterpreter> k;
};

// Ball 4.8 (table -0.1, TOOL CALL -0.1) on the slope (0.6, 0, 0.8) (written unnormalised): the
// tip goes from (10, 0, 0) to (9.88, 0, 0.04). Toroid: (0, 10, 0) + (0, -0.26, 0.02). End mill:
// across the tool only, by DR; where the normal is along the tool the face touches and the point
// stays.
TEST_F(LineNormalTest, EveryCutterShapeTouchesWhereTheCamSystemsDid) {
    ASSERT_EQ(run("mill",
                  "1 TOOL CALL 1 Z S1000 DR-0.1 DR2-0.1\n2 L X+0 Y+0 Z+10 R0 FMAX\n"
                  "3 LN X+10 Y+0 Z+0 NX+3 NY+0 NZ+4 F100\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(9.88, 0.0, 0.04);
    ASSERT_EQ(run("mill", "1 TOOL CALL 3 Z S1000\n2 LN X+0 Y+10 Z+0 NX+0 NY+0.6 NZ+0.8 F100\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(0.0, 9.74, 0.02);
    ASSERT_EQ(run("mill", "1 TOOL CALL 2 Z S1000\n2 LN X+10 Y+5 Z+1 NX+0.6 NY+0 NZ+0.8 F100\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(9.5, 5.0, 1.0);
    ASSERT_EQ(run("mill", "1 TOOL CALL 2 Z S1000\n2 LN X+10 Y+5 Z+1 NX+0 NY+0 NZ+1 F100\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(10.0, 5.0, 1.0);
}

// A tool larger than the CAM system's (ball 5.2) stops the run at the LN block unless M107
// permits it (in an earlier block or the LN block itself, until M108). Permitted, the tip moves
// by 0.2 ((0.6, 0, 0.8) - (0, 0, 1)) = (0.12, 0, -0.04).
TEST_F(LineNormalTest, PositiveOversizesNeedM107) {
    const std::string lnBlock = "LN X+10 Y+0 Z+0 NX+0.6 NY+0 NZ+0.8 F100";
    ASSERT_EQ(run("mill", "1 TOOL CALL 4 Z S1000\n2 " + lnBlock + "\n"), interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("M107"), std::string::npos) << firstError();
    ASSERT_EQ(run("mill", "1 TOOL CALL 4 Z S1000\n2 M107\n3 " + lnBlock + "\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(10.12, 0.0, -0.04);
    ASSERT_EQ(run("mill", "1 TOOL CALL 4 Z S1000\n2 " + lnBlock + " M107\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(10.12, 0.0, -0.04);
    EXPECT_EQ(run("mill", "1 TOOL CALL 4 Z S1000\n2 M107\n3 M108\n4 " + lnBlock + "\n"),
              interp::RunStatus::Failed);
    // A positive oversize of the TOOL CALL alone counts too (the TNC's own example: DR2 +0.3).
    EXPECT_EQ(run("mill", "1 TOOL CALL 7 Z S1000 DR2+0.3\n2 " + lnBlock + "\n"),
              interp::RunStatus::Failed);
}

// R2 + DR2 must lie between 0 and R + DR: a ball worn to 4.5 with its corner still 5, a corner of
// -0.1. As before, RL/RR and a vector without length are refused.
TEST_F(LineNormalTest, ImpossibleCuttersAndWrongBlocksAreErrors) {
    const std::string lnBlock = "LN X+10 Y+0 Z+0 NX+0 NY+0 NZ+1 F100";
    for (const char* tool : {"5", "6"}) {
        SCOPED_TRACE(tool);
        ASSERT_EQ(run("mill", std::string("1 TOOL CALL ") + tool + " Z S1000\n2 " + lnBlock + "\n"),
                  interp::RunStatus::Failed);
        EXPECT_NE(firstError().find("corner radius"), std::string::npos) << firstError();
    }
    EXPECT_EQ(run("mill", "1 TOOL CALL 7 Z\n2 L X+0 Y+0 RL F100\n3 " + lnBlock + "\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(run("mill", "1 TOOL CALL 7 Z\n2 LN X+10 Y+0 Z+0 NX+0 NY+0 NZ+0 F100\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(run("mill", "1 TOOL CALL 7 Z\n2 LN X+10 Y+0 Z+0 NX+0 NY+0 F100\n"),
              interp::RunStatus::Failed);
}

// mill5 (B table about Y, C on it, the pivot at the workpiece origin). Under M128 TX TY TZ =
// (sin 30, 0, cos 30) turns the tables to B+30 C0 (the nearer of B+30 C0 and B-30 C180) while the
// tip stays at (0, 0, 50): the axes go to Ry(-30) (0, 0, 50) = (-25, 0, 25 sqrt 3). Without TX TY
// TZ the tool stands along the normal: the same for the normal (0.5, 0, 0.866), where a ball
// smaller than the CAM system's (4.9) touches with its pole, so the tip stays. The ball of 4.9
// turned 30 deg on the floor (normal Z) moves the tip by -0.1 ((0, 0, 1) - (sin 30, 0, cos 30)).
// Without TCPM the TNC ignores TX TY TZ: the tables stand.
TEST_F(LineNormalTest, TcpmTurnsTheToolToItsDirectionOrToTheNormal) {
    const double c = std::sqrt(3.0) / 2.0, s = 0.5;
    const std::string turned = "LN X+0 Y+0 Z+50 NX+0 NY+0 NZ+1 TX+0.5 TY+0 TZ+0.8660254038 F1000";
    const std::string alongNormal = "LN X+0 Y+0 Z+50 NX+0.5 NY+0 NZ+0.8660254038 F1000";
    const Vec3 worn(0.1 * s, 0.0, 50.0 - 0.1 * (1.0 - c));  // the tip of the ball of 4.9
    const struct {
        const char* tool;
        std::string block;
        Vec3 tip;
    } cases[] = {{"7", turned, Vec3(0.0, 0.0, 50.0)},
                 {"1", alongNormal, Vec3(0.0, 0.0, 50.0)},
                 {"1", turned, worn}};
    for (const auto& each : cases) {
        SCOPED_TRACE(std::string(each.tool) + ": " + each.block);
        ASSERT_EQ(run("mill5", std::string("1 TOOL CALL ") + each.tool +
                                   " Z S1000\n2 L X+0 Y+0 Z+50 R0 FMAX\n3 M128\n4 " + each.block +
                                   "\n5 M129\n"),
                  interp::RunStatus::Finished)
            << firstError();
        const Pose axes = lastMoveOf(4);
        EXPECT_NEAR(axes[Axis::B], 30.0, 1e-6);
        EXPECT_NEAR(axes[Axis::C], 0.0, 1e-9);
        // Ry(-30): the table turns the tip back by 30 deg about Y.
        EXPECT_NEAR(axes[Axis::X], c * each.tip.x() - s * each.tip.z(), 1e-6);
        EXPECT_NEAR(axes[Axis::Y], 0.0, 1e-9);
        EXPECT_NEAR(axes[Axis::Z], s * each.tip.x() + c * each.tip.z(), 1e-6);
    }
    ASSERT_EQ(run("mill5",
                  "1 TOOL CALL 7 Z S1000\n2 L X+0 Y+0 Z+60 R0 FMAX\n"
                  "3 LN X+0 Y+0 Z+50 NX+0 NY+0 NZ+1 TX+0.5 TY+0 TZ+0.866 F1000\n"),
              interp::RunStatus::Finished)
        << firstError();
    const Pose standing = lastMoveOf(3);
    EXPECT_NEAR(standing[Axis::B], 0.0, 1e-12);
    EXPECT_NEAR(standing[Axis::Z], 50.0, 1e-9);
}

}  // namespace
}  // namespace kerf::klartext
